// What planning one satellite pass costs. The plan is made on the daemon's loop
// once per pass (docs/satellites.md), so its worst case matters: 200 synthetic passes per mount
// kind (a third crossing north, a third near the zenith, a third low, 400–900 km), timed one by
// one with the steady clock. Prints a Markdown table.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "azt/sim/pass_sim.hpp"
#include "azt/track/pass_plan.hpp"

namespace {

using azt::track::MountGeometry;

MountGeometry mount(double az_max, double el_max) {
  MountGeometry m;
  m.az = azt::control::AzimuthRange{0.0, az_max};
  m.el = azt::control::ElevationRange{0.0, el_max};
  return m;
}

/// The same mix of passes as PassSimulation.TwoHundredPassesPerMountKindKeepTheirPlannedLoss.
std::vector<std::vector<azt::track::SkyPoint>> passes() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::vector<azt::track::SkyPoint>> out;
  for (int i = 0; i < 200; ++i) {
    azt::sim::SyntheticPass p;
    p.altitude_km = 400.0 + 500.0 * unit(rng);
    p.nearest_az_deg = 360.0 * unit(rng);
    if (i % 3 == 0) {
      p.nearest_az_deg = -20.0 + 40.0 * unit(rng);
      p.offset_deg = 3.0 + 10.0 * unit(rng);
    } else if (i % 3 == 1) {
      p.offset_deg = 1.5 * unit(rng);
    } else {
      p.offset_deg = 14.0 + 4.0 * unit(rng);
    }
    p.clockwise = unit(rng) < 0.5;
    auto sky = azt::sim::synthetic_pass(p);
    if (sky.size() >= 10) out.push_back(std::move(sky));
  }
  return out;
}

}  // namespace

int main() {
  const auto sky = passes();
  std::printf("| mount | passes | mean ms per plan | worst ms | samples in the worst |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const auto& [name, m] : {std::pair{"0–360°", mount(360.0, 90.0)},
                                {"0–450°", mount(450.0, 90.0)},
                                {"flip", mount(360.0, 180.0)}}) {
    double total = 0.0;
    double worst = 0.0;
    std::size_t worst_n = 0;
    for (const auto& s : sky) {
      const auto t0 = std::chrono::steady_clock::now();
      auto plan = azt::track::plan_pass(s, m, 180.0);
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (!plan) return 1;
      total += ms;
      if (ms > worst) {
        worst = ms;
        worst_n = s.size();
      }
    }
    std::printf("| %s | %zu | %.2f | %.2f | %zu |\n", name, sky.size(),
                total / static_cast<double>(sky.size()), worst, worst_n);
  }
  return 0;
}
