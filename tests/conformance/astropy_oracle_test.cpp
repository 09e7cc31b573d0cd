// Fixed radio sources against astropy (Debian python3-astropy 5.2.1, offline), at seeded random
// instants 1973–2035 and random stations: the catalogue sources in turn, plus random ICRS
// directions. Geometric (airless) az/el only.
//
// astropy is run once, vectorised, by tests/conformance/astropy_oracle.py under /usr/bin/python3
// (pyenv's python3 cannot see Debian's modules: /work/shared/oracles/README.md §3). astropy takes
// UT1 − UTC from its bundled IERS-B table (to 2022-12-01; past it the last value is held) and
// reports it; we use the very same DUT1 so both run at the same UT1. astropy also applies polar
// motion from that table (up to ~0.6″ on a star's az/el, README "Pitfalls"), which azeltrack does
// not: hence the 1″ bar, and the report split at the table's end.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "azt/astro/catalogue.hpp"
#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/observer.hpp"
#include "azt/astro/refraction.hpp"
#include "azt/astro/sky.hpp"
#include "azt/astro/target.hpp"
#include "azt/astro/time_scales.hpp"
#include "oracle_support.hpp"

namespace azt::astro {
namespace {

namespace oracle = azt::oracle;

constexpr std::uint64_t kDefaultSeed = 19730101;
constexpr int kCaseCount = 600;
constexpr int kFirstYear = 1973;
constexpr int kEndYear = 2036;  // exclusive
// 1972-01-01, the leap-second table's first day: its eve has no TAI−UTC.
constexpr double kLeapTableStartMjd = 41317.0;
// Every third case is a random direction, the others walk through the catalogue.
constexpr int kRandomDirectionEvery = 3;
// Last day of astropy's bundled IERS-B table (MJD 59912 = 2022-12-01, read from
// astropy.utils.iers.IERS_B.open()); after it UT1−UTC and polar motion are held constant.
constexpr double kIersBEndMjd = 59912.0;
constexpr double kUnixEpochMjd = 40587.0;

// astropy with polar motion: the brief's bar (polar motion alone reaches ~0.6″).
constexpr double kBarArcsec = 1.0;
// astropy with polar motion zeroed: what is left is IAU 2000B vs 2006/2000A precession-nutation
// (≤ 1 mas, ERFA nut00b.c), TT used as TDB and ephemeris details of aberration and deflection.
constexpr double kNoPolarMotionBarArcsec = 0.01;

struct StarCase {
  int index = 0;
  double unix_s = 0.0;
  oracle::RandomStation station;
  Target target;
  std::string label;
};

struct AstropyResult {
  double az_deg = 0.0;  ///< astropy's own (with polar motion)
  double alt_deg = 0.0;
  double az_nopm_deg = 0.0;  ///< the same transform with polar motion forced to zero
  double alt_nopm_deg = 0.0;
  double dut1_s = 0.0;
};

std::string fmt(double value) { return oracle::format_number(value, 17); }
/// Short numbers for labels: the seed and case index reproduce a case exactly.
std::string short_fmt(double value) { return oracle::format_number(value, 9); }

/// kCaseCount random instants, then one on the eve of every leap second since 1972-07-01.
std::vector<double> case_instants(oracle::CaseRng& rng) {
  std::vector<double> instants;
  instants.reserve(static_cast<std::size_t>(kCaseCount));
  for (int i = 0; i < kCaseCount; ++i) {
    instants.push_back(oracle::random_unix_seconds(rng, kFirstYear, kEndYear));
  }
  std::vector<double> step_mjds;
  for (const auto& step : LeapSecondTable::builtin().steps()) {
    if (step.mjd_utc > kLeapTableStartMjd) step_mjds.push_back(step.mjd_utc);
  }
  const auto eves = oracle::leap_eve_unix_seconds(step_mjds, rng);
  instants.insert(instants.end(), eves.begin(), eves.end());
  return instants;
}

std::vector<StarCase> make_cases(std::uint64_t seed) {
  oracle::CaseRng rng(seed);
  const auto sources = radio_sources();
  const auto instants = case_instants(rng);
  std::vector<StarCase> cases;
  std::size_t next_source = 0;
  for (std::size_t i = 0; i < instants.size(); ++i) {
    StarCase c;
    c.index = static_cast<int>(i);
    c.unix_s = instants[i];
    c.station = oracle::random_station(rng);
    if (i % kRandomDirectionEvery == kRandomDirectionEvery - 1 || sources.empty()) {
      // Uniform on the sphere: Dec = asin(u), u uniform in [−1, 1).
      const double ra = rng.uniform(0.0, 360.0);
      const double dec = std::asin(rng.uniform(-1.0, 1.0)) * 180.0 / std::numbers::pi;
      c.target = Target::radec(ra, dec).value();
    } else {
      c.target = Target::radio_source(sources[next_source++ % sources.size()]);
    }
    c.label = std::string(i < kCaseCount ? "case " : "leap-eve case ") + std::to_string(i) +
              " seed " + std::to_string(seed) + ": " + oracle::unix_to_iso8601(c.unix_s) +
              "Z lat " + short_fmt(c.station.lat_deg) + " lon " + short_fmt(c.station.lon_deg) +
              " h " + short_fmt(c.station.height_m) + " " + c.target.name + " (RA " +
              short_fmt(c.target.ra_deg) + " Dec " + short_fmt(c.target.dec_deg) + ")";
    cases.push_back(std::move(c));
  }
  return cases;
}

/// The cases as the script's CSV. The instant goes as ISO 8601 UTC, not as a Julian date: on a
/// day that ends in a leap second astropy (ERFA) spreads the JD fraction over 86401 s, so a JD
/// built on 86400-s days would be read up to 1 s late (found at 1982-06-30T19:19:31: 0.805 s).
std::string cases_csv(const std::vector<StarCase>& cases) {
  std::string csv = "id,utc_iso,lat_deg,lon_deg,height_m,ra_deg,dec_deg\n";
  for (const StarCase& c : cases) {
    csv += std::to_string(c.index) + "," + oracle::unix_to_iso8601(c.unix_s) + "," +
           fmt(c.station.lat_deg) + "," + fmt(c.station.lon_deg) + "," + fmt(c.station.height_m) +
           "," + fmt(c.target.ra_deg) + "," + fmt(c.target.dec_deg) + "\n";
  }
  return csv;
}

struct AstropyRun {
  std::map<int, AstropyResult> results;
  std::string log;
  double wall_s = 0.0;
  std::string error;
};

AstropyRun run_astropy(const std::vector<StarCase>& cases) {
  AstropyRun run;
  const auto started = std::chrono::steady_clock::now();
  const auto text =
      oracle::run_csv_oracle(AZT_ASTROPY_ORACLE, "", cases_csv(cases), run.error, &run.log);
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!text) return run;
  const auto lines = oracle::split_lines(*text);
  for (std::size_t i = 1; i < lines.size(); ++i) {  // line 0 is the header
    const auto f = oracle::split_fields(lines[i], ',');
    constexpr std::size_t kColumns = 6;
    std::vector<double> v;
    for (const auto field : f) {
      if (const auto x = oracle::parse_double(field)) v.push_back(*x);
    }
    if (f.size() != kColumns || v.size() != kColumns) {
      run.error = "bad astropy output line: " + std::string(lines[i]);
      return run;
    }
    run.results[static_cast<int>(v[0])] = AstropyResult{v[1], v[2], v[3], v[4], v[5]};
  }
  return run;
}

TEST(AstropyOracle, RadioSourcesGeometricAzEl) {
  const std::uint64_t seed = oracle::oracle_seed(kDefaultSeed);
  const auto cases = make_cases(seed);
  const AstropyRun astropy = run_astropy(cases);
  ASSERT_TRUE(astropy.error.empty()) << astropy.error << "\n" << astropy.log;
  ASSERT_EQ(astropy.results.size(), cases.size()) << astropy.log;

  const ErfaEphemeris ephemeris;
  const auto airless = Atmosphere::make(0.0, 15.0, 0.0, RefractionModel::None);
  ASSERT_TRUE(airless.ok()) << airless.error().message;

  // [0]: instants inside astropy's IERS-B table (polar motion applied there), [1]: after it.
  oracle::Stats az[2];
  oracle::Stats el[2];
  oracle::Stats az_nopm;
  oracle::Stats el_nopm;
  oracle::Stats dut1_s;
  const auto started = std::chrono::steady_clock::now();
  for (const StarCase& c : cases) {
    const AstropyResult& ref = astropy.results.at(c.index);
    dut1_s.add(ref.dut1_s, c.label);
    const auto time = make_time_scales(UtcInstant::from_unix_seconds(c.unix_s), ref.dut1_s,
                                       LeapSecondTable::builtin());
    ASSERT_TRUE(time.ok()) << c.label << ": " << time.error().message;
    const auto epoch = make_epoch(ephemeris, *time);
    ASSERT_TRUE(epoch.ok()) << c.label << ": " << epoch.error().message;
    const auto observer = Observer::make(c.station.lat_deg, c.station.lon_deg, c.station.height_m);
    ASSERT_TRUE(observer.ok()) << c.label << ": " << observer.error().message;
    const Station station = make_station(*epoch, *observer);
    const auto seen = observe(c.target, ephemeris, *epoch, station, *airless);
    ASSERT_TRUE(seen.ok()) << c.label << ": " << seen.error().message;

    const std::size_t era = c.unix_s / 86400.0 + kUnixEpochMjd > kIersBEndMjd ? 1 : 0;
    const std::string label = c.label + " DUT1 " + short_fmt(ref.dut1_s);
    az[era].add(oracle::az_on_sky_diff_arcsec(seen->place.az_deg, ref.az_deg, ref.alt_deg), label);
    el[era].add((seen->place.el_geometric_deg - ref.alt_deg) * oracle::kArcsecPerDeg, label);
    az_nopm.add(
        oracle::az_on_sky_diff_arcsec(seen->place.az_deg, ref.az_nopm_deg, ref.alt_nopm_deg),
        label);
    el_nopm.add((seen->place.el_geometric_deg - ref.alt_nopm_deg) * oracle::kArcsecPerDeg, label);
  }
  const double ours_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  const std::vector<oracle::SummaryRow> rows = {
      {"az*cos(el), to 2022-12-01", "arcsec", az[0], kBarArcsec},
      {"el, to 2022-12-01", "arcsec", el[0], kBarArcsec},
      {"az*cos(el), after (IERS held)", "arcsec", az[1], kBarArcsec},
      {"el, after (IERS held)", "arcsec", el[1], kBarArcsec},
      {"az*cos(el), astropy without PM", "arcsec", az_nopm, kNoPolarMotionBarArcsec},
      {"el, astropy without PM", "arcsec", el_nopm, kNoPolarMotionBarArcsec},
      {"astropy UT1-UTC used as DUT1", "s", dut1_s, std::nullopt},
  };
  std::cout << oracle::format_summary("astropy vs azeltrack, fixed ICRS sources, airless", rows);
  std::cout << "cases " << cases.size() << " (seed " << seed << ", " << radio_sources().size()
            << " catalogue sources + every " << kRandomDirectionEvery
            << "rd a random direction; the last " << cases.size() - kCaseCount
            << " on leap-second eves); astropy wall time " << astropy.wall_s
            << " s; our computation " << ours_s << " s\n"
            << "astropy log: " << astropy.log;

  for (std::size_t era = 0; era < 2; ++era) {
    EXPECT_LE(az[era].max_abs(), kBarArcsec)
        << "az*cos(el) (seed " << seed << "): max " << az[era].max_abs() << ", rms "
        << az[era].rms() << ", worst " << az[era].worst_label();
    EXPECT_LE(el[era].max_abs(), kBarArcsec)
        << "el (seed " << seed << "): max " << el[era].max_abs() << ", rms " << el[era].rms()
        << ", worst " << el[era].worst_label();
  }
  EXPECT_LE(az_nopm.max_abs(), kNoPolarMotionBarArcsec)
      << "az*cos(el) without polar motion (seed " << seed << "): max " << az_nopm.max_abs()
      << ", worst " << az_nopm.worst_label();
  EXPECT_LE(el_nopm.max_abs(), kNoPolarMotionBarArcsec)
      << "el without polar motion (seed " << seed << "): max " << el_nopm.max_abs() << ", worst "
      << el_nopm.worst_label();
}

}  // namespace
}  // namespace azt::astro
