// Satellite benchmark (docs/satellites.md "Speed"): SGP4 propagations per second and a 7-day pass
// search for 100 satellites, beside python3-sgp4 (Debian builds only its pure-Python propagator)
// and skyfield's find_events on the same element sets, in one run. Prints a Markdown table.
//
// Usage: azt_sat_bench [path/to/sat_bench.py]
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "azt/astro/time_scales.hpp"
#include "azt/orbit/look_angles.hpp"
#include "azt/orbit/passes.hpp"
#include "azt/orbit/sgp4.hpp"
#include "azt/orbit/tle.hpp"

namespace {

using namespace azt;
using Clock = std::chrono::steady_clock;

std::string with_checksum(std::string line) {
  line.resize(68, ' ');
  return line + std::to_string(orbit::tle_checksum(line));
}

/// 100 LEO element sets: the ISS's, spread in node, anomaly, inclination and mean motion.
std::string catalogue() {
  std::string out;
  for (int i = 0; i < 100; ++i) {
    char l1[80];
    char l2[80];
    std::snprintf(l1, sizeof l1,
                  "1 %05dU 24001A   26328.50000000  .00001000  00000-0  10000-3 0  999", 50000 + i);
    std::snprintf(l2, sizeof l2, "2 %05d %8.4f %8.4f 0005000 %8.4f %8.4f %11.8f    1", 50000 + i,
                  40.0 + 0.5 * i, std::fmod(37.0 * i, 360.0), std::fmod(11.0 * i, 360.0),
                  std::fmod(73.0 * i, 360.0), 14.0 + 0.02 * i);
    out += "SAT-" + std::to_string(i) + "\n" + with_checksum(l1) + "\n" + with_checksum(l2) + "\n";
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  // The script's place is known at build time, so the benchmark runs from any directory.
  const std::string script = argc > 1 ? argv[1] : AZT_SAT_BENCH_SCRIPT;
  const std::string text = catalogue();
  const std::string path = "/tmp/azt_sat_bench.tle";
  std::ofstream(path) << text;
  const auto parsed = orbit::parse_tle_catalogue(text);
  if (parsed.sets.size() != 100) {
    std::cerr << "catalogue: " << parsed.sets.size() << " sets; "
              << (parsed.errors.empty() ? "" : parsed.errors.front()) << '\n';
    return 1;
  }
  std::vector<orbit::Sgp4> sats;
  for (const auto& e : parsed.sets) sats.push_back(orbit::Sgp4::make(e).value());

  // Propagations per second (the same time steps as the Python side: one minute apart).
  const int n = 2'000'000;
  double sink = 0.0;
  auto t0 = Clock::now();
  for (int i = 0; i < n; ++i) {
    if (auto s = sats[0].at_minutes(static_cast<double>(i % 100000))) sink += s->r_km[0];
  }
  const double prop_s = std::chrono::duration<double>(Clock::now() - t0).count();
  const double ours_rate = n / prop_s;

  // A 7-day pass search for all 100 from a site at 46.2 N 79.4 W.
  const auto site = astro::Observer::make(46.2, -79.4, 0.0).value();
  const auto from = astro::parse_iso8601_utc("2026-11-24T12:00:00Z").value();
  t0 = Clock::now();
  std::size_t passes = 0;
  for (const auto& sat : sats) {
    const orbit::LookFunction look = [&](double t) -> Result<orbit::LookAngles> {
      astro::UtcInstant u = from;
      u.jd.jd2 += t / 86400.0;
      auto s = sat.at_jd(u.jd.jd1, u.jd.jd2);
      if (!s) return s.error();
      return orbit::look_angles(s->r_km, s->v_km_s, u.jd, site);
    };
    const auto& e = sat.elements();
    auto found = orbit::find_passes(
        look, orbit::orbit_pass_search(e.mean_motion_rev_day, e.eccentricity, 0.0, 7 * 86400.0,
                                       orbit::HorizonMask::flat(0.0)));
    if (found) passes += found.value().size();
  }
  const double search_s = std::chrono::duration<double>(Clock::now() - t0).count();

  double py_rate = 0.0;
  double py_search = 0.0;
  long py_passes = 0;
  const std::string cmd =
      "/usr/bin/python3 " + script + " " + path + " 46.2 -79.4 2026-11-24T12:00:00 7";
  int py_status = -1;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char line[256];
    while (std::fgets(line, sizeof line, p) != nullptr) {
      std::istringstream in(line);
      std::string key;
      in >> key;
      if (key == "propagations_per_s") in >> py_rate;
      if (key == "pass_search_s") in >> py_search >> py_passes;
    }
    const int status = ::pclose(p);
    py_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  // A benchmark that cannot compare says so and fails, instead of printing a ratio of 0.
  if (py_status != 0 || py_rate <= 0.0 || py_search <= 0.0) {
    std::fprintf(stderr,
                 "azt_sat_bench: the python3-sgp4/skyfield side did not run (`%s` exited with "
                 "code %d); install python3-sgp4 and python3-skyfield (scripts/install-deps)\n",
                 cmd.c_str(), py_status);
    return 1;
  }
  std::printf("| measure | azeltrack | python3-sgp4 / skyfield | ratio |\n|---|---|---|---|\n");
  std::printf("| SGP4 propagations per second | %.0f | %.0f | %.0f× |\n", ours_rate, py_rate,
              ours_rate / py_rate);
  std::printf(
      "| 7-day pass search, 100 LEO satellites | %.3f s (%zu passes) | %.1f s (%ld rises) | %.0f× "
      "|\n",
      search_s, passes, py_search, py_passes, py_search / search_s);
  std::fprintf(stderr, "(checksum %g)\n", sink);
  return 0;
}
