// Satellite look angles and passes against skyfield 1.45 + python-sgp4 (Debian, offline;
// docs/satellites.md "Accuracy, measured"): seeded random instants and stations over the
// verification set's element sets (those that propagate) plus an ISS set. Bars: az·cos(el) and el
// 1″, range 1 m, range rate 1 m/s, rise and set within 1 s of skyfield's event times refined by
// bisection on its own elevation.
//
// The same UT1 on both sides: skyfield reports the UT1 − UTC it used, and it is passed as DUT1.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "azt/astro/time_scales.hpp"
#include "azt/orbit/look_angles.hpp"
#include "azt/orbit/passes.hpp"
#include "azt/orbit/sgp4.hpp"
#include "azt/orbit/tle.hpp"
#include "oracle_support.hpp"

namespace azt::orbit {
namespace {

namespace oracle = azt::oracle;

constexpr std::uint64_t kDefaultSeed = 20261124;
constexpr int kLookCases = 400;
constexpr int kPassCases = 12;
constexpr double kUnixEpochJd = 2440587.5;

struct Set {
  std::string line1;
  std::string line2;
  Elements elements;
};

/// The verification set's element sets (only the 69 columns of each line), plus an ISS set.
std::vector<Set> element_sets() {
  std::vector<Set> out;
  const auto text = oracle::read_file("/usr/lib/python3/dist-packages/sgp4/SGP4-VER.TLE");
  if (!text) return out;
  const auto lines = oracle::split_lines(*text);
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    if (lines[i].substr(0, 2) != "1 " || lines[i + 1].substr(0, 2) != "2 ") continue;
    Set s{std::string(lines[i].substr(0, 69)), std::string(lines[i + 1].substr(0, 69)), {}};
    auto e = parse_tle(s.line1, s.line2, {}, TleOptions{false});
    if (!e) continue;
    s.elements = e.value();
    out.push_back(std::move(s));
  }
  Set iss{"1 25544U 98067A   24061.52083333  .00016717  00000-0  30119-3 0  9999",
          "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.49815488441113",
          {}};
  iss.elements = parse_tle(iss.line1, iss.line2).value();
  out.push_back(iss);
  return out;
}

double epoch_unix(const Elements& e) {
  return ((e.epoch_jd - kUnixEpochJd) + e.epoch_jd_frac) * 86400.0;
}

std::string csv_number(double v) { return oracle::format_number(v, 17); }

std::map<int, std::vector<double>> run_oracle(const std::string& mode, const std::string& cases,
                                              std::string& error, std::vector<std::string>* rows) {
  std::map<int, std::vector<double>> result;
  const auto text = oracle::run_csv_oracle(AZT_SKYFIELD_ORACLE, mode, cases, error);
  if (!text) {
    if (error.empty()) error = "the skyfield oracle wrote nothing";
    return result;
  }
  const auto lines = oracle::split_lines(*text);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (rows != nullptr) {
      rows->emplace_back(lines[i]);
      continue;
    }
    std::vector<double> v;
    for (const auto f : oracle::split_fields(lines[i], ',')) {
      const auto x = oracle::parse_double(f);
      v.push_back(x ? *x : std::nan(""));
    }
    result[static_cast<int>(v[0])] = v;
  }
  return result;
}

TEST(SkyfieldSatOracle, LookAnglesRangeAndRangeRate) {
  const auto sets = element_sets();
  ASSERT_GT(sets.size(), 20U)
      << "SGP4-VER.TLE missing: install python3-sgp4 (scripts/install-deps)";
  const std::uint64_t seed = oracle::oracle_seed(kDefaultSeed);
  oracle::CaseRng rng(seed);
  struct Case {
    std::size_t set;
    double unix_s;
    oracle::RandomStation station;
  };
  std::vector<Case> cases;
  std::string csv = "id,line1,line2,utc_iso,lat_deg,lon_deg,height_m\n";
  for (int i = 0; i < kLookCases; ++i) {
    Case c{rng.index(sets.size()), 0.0, oracle::random_station(rng)};
    // Within three days of the epoch, to the millisecond (what the ISO text carries).
    c.unix_s =
        std::round((epoch_unix(sets[c.set].elements) + rng.uniform(-3.0, 3.0) * 86400.0) * 1000.0) /
        1000.0;
    csv += std::to_string(i) + "," + sets[c.set].line1 + "," + sets[c.set].line2 + "," +
           oracle::unix_to_iso8601(c.unix_s) + "," + csv_number(c.station.lat_deg) + "," +
           csv_number(c.station.lon_deg) + "," + csv_number(c.station.height_m) + "\n";
    cases.push_back(c);
  }
  std::string error;
  const auto ref = run_oracle("look", csv, error, nullptr);
  ASSERT_TRUE(error.empty()) << error;
  ASSERT_EQ(ref.size(), cases.size());

  oracle::Stats az, el, range_m, rate_m_s;
  int both_failed = 0;
  for (int i = 0; i < kLookCases; ++i) {
    const Case& c = cases[static_cast<std::size_t>(i)];
    const auto& r = ref.at(i);
    const std::string label = "case " + std::to_string(i) + " seed " + std::to_string(seed) +
                              " sat " + sets[c.set].elements.catalog + " at " +
                              oracle::unix_to_iso8601(c.unix_s);
    const auto sgp4 = Sgp4::make(sets[c.set].elements);
    ASSERT_TRUE(sgp4.ok()) << label;
    const astro::UtcInstant utc = astro::UtcInstant::from_unix_seconds(c.unix_s);
    const auto state = sgp4.value().at_jd(utc.jd.jd1, utc.jd.jd2);
    if (std::isnan(r[1])) {
      EXPECT_FALSE(state.ok()) << label << ": skyfield failed, we propagated";
      ++both_failed;
      continue;
    }
    ASSERT_TRUE(state.ok()) << label << ": " << state.error().message;
    const astro::JulianDate ut1{utc.jd.jd1, utc.jd.jd2 + r[5] / 86400.0};
    const auto site =
        astro::Observer::make(c.station.lat_deg, c.station.lon_deg, c.station.height_m);
    const LookAngles l = look_angles(state->r_km, state->v_km_s, ut1, site.value());
    az.add(oracle::az_on_sky_diff_arcsec(l.az_deg, r[1], r[2]), label);
    el.add((l.el_deg - r[2]) * oracle::kArcsecPerDeg, label);
    range_m.add((l.range_km - r[3]) * 1000.0, label);
    rate_m_s.add((l.range_rate_km_s - r[4]) * 1000.0, label);
  }
  const std::vector<oracle::SummaryRow> rows = {
      {"az*cos(el)", "arcsec", az, 1.0},
      {"el", "arcsec", el, 1.0},
      {"range", "m", range_m, 1.0},
      {"range rate", "m/s", rate_m_s, 1.0},
  };
  std::cout << oracle::format_summary("skyfield vs azeltrack, satellites (SGP4, geometric)", rows)
            << kLookCases << " cases (seed " << seed << "), " << sets.size() << " element sets; "
            << both_failed << " where both refuse to propagate\n";
  for (const auto& row : rows) {
    EXPECT_LE(row.stats.max_abs(), *row.bar) << row.quantity << ": " << row.stats.worst_label();
  }
}

TEST(SkyfieldSatOracle, RiseAndSetTimes) {
  auto sets = element_sets();
  ASSERT_GT(sets.size(), 20U);
  // Near-earth orbits (period under 225 min) give passes a day can hold several of.
  std::erase_if(sets, [](const Set& s) { return s.elements.mean_motion_rev_day < 6.4; });
  // And those that propagate through the windows (the set holds decaying and broken orbits).
  std::erase_if(sets, [](const Set& s) {
    const auto sgp4 = Sgp4::make(s.elements);
    if (!sgp4) return true;
    for (double minutes = -1.5 * 1440.0; minutes <= 2.5 * 1440.0; minutes += 30.0) {
      if (!sgp4.value().at_minutes(minutes)) return true;
    }
    return false;
  });
  const std::uint64_t seed = oracle::oracle_seed(kDefaultSeed) + 1;
  oracle::CaseRng rng(seed);
  std::string csv = "id,line1,line2,from_iso,hours,lat_deg,lon_deg,height_m,min_el_deg\n";
  struct Case {
    std::size_t set;
    double from_unix;
    oracle::RandomStation station;
    double min_el;
  };
  std::vector<Case> cases;
  for (int i = 0; i < kPassCases; ++i) {
    Case c{rng.index(sets.size()), 0.0, oracle::random_station(rng), i % 3 == 0 ? 10.0 : 0.0};
    c.from_unix = std::round(epoch_unix(sets[c.set].elements) + rng.uniform(-1.0, 1.0) * 86400.0);
    csv += std::to_string(i) + "," + sets[c.set].line1 + "," + sets[c.set].line2 + "," +
           oracle::unix_to_iso8601(c.from_unix) + ",24," + csv_number(c.station.lat_deg) + "," +
           csv_number(c.station.lon_deg) + "," + csv_number(c.station.height_m) + "," +
           csv_number(c.min_el) + "\n";
    cases.push_back(c);
  }
  std::string error;
  std::vector<std::string> events;
  (void)run_oracle("passes", csv, error, &events);
  ASSERT_TRUE(error.empty()) << error;

  oracle::Stats rise, set;
  std::size_t compared = 0;
  std::map<int, std::vector<Pass>> ours;
  for (int i = 0; i < kPassCases; ++i) {
    const Case& c = cases[static_cast<std::size_t>(i)];
    const auto sgp4 = Sgp4::make(sets[c.set].elements).value();
    std::optional<double> dut1;
    for (const auto& line : events) {
      const auto f = oracle::split_fields(line, ',');
      if (f.size() == 6 && oracle::parse_double(f[0]) == i) dut1 = oracle::parse_double(f[5]);
    }
    const auto site =
        astro::Observer::make(c.station.lat_deg, c.station.lon_deg, c.station.height_m);
    const LookFunction at = [&](double t) -> Result<LookAngles> {
      const astro::UtcInstant utc = astro::UtcInstant::from_unix_seconds(c.from_unix + t);
      auto s = sgp4.at_jd(utc.jd.jd1, utc.jd.jd2);
      if (!s) return s.error();
      return look_angles(s->r_km, s->v_km_s,
                         {utc.jd.jd1, utc.jd.jd2 + dut1.value_or(0.0) / 86400.0}, site.value());
    };
    const auto e = sgp4.elements();
    auto found = find_passes(at, orbit_pass_search(e.mean_motion_rev_day, e.eccentricity, 0.0,
                                                   86400.0, HorizonMask::flat(c.min_el)));
    ASSERT_TRUE(found.ok()) << found.error().message;
    ours[i] = found.value();
  }
  for (const auto& line : events) {
    const auto f = oracle::split_fields(line, ',');
    ASSERT_EQ(f.size(), 6U) << line;
    const int id = static_cast<int>(*oracle::parse_double(f[0]));
    const std::string kind(f[1]);
    if (kind == "culminate") continue;
    const double t = *oracle::parse_double(f[2]);
    const std::string label = "case " + std::to_string(id) + " seed " + std::to_string(seed) + " " +
                              kind + " at +" + std::to_string(t) + " s";
    double best = 1e9;
    for (const Pass& p : ours[id]) {
      if (kind == "rise" && !p.starts_before_window) best = std::min(best, std::fabs(p.aos_s - t));
      if (kind == "set" && !p.ends_after_window) best = std::min(best, std::fabs(p.los_s - t));
    }
    EXPECT_LE(best, 1.0) << label << ": no pass of ours within 1 s";
    (kind == "rise" ? rise : set).add(best, label);
    ++compared;
  }
  std::size_t our_passes = 0;
  for (const auto& [id, list] : ours) our_passes += list.size();
  const std::vector<oracle::SummaryRow> rows = {{"rise (AOS)", "s", rise, 1.0},
                                                {"set (LOS)", "s", set, 1.0}};
  std::cout << oracle::format_summary("skyfield (refined) vs azeltrack, pass times", rows)
            << kPassCases << " day-long windows (seed " << seed << "), " << compared
            << " events compared, " << our_passes << " passes found by azeltrack\n";
  EXPECT_GT(compared, 20U);
}

}  // namespace
}  // namespace azt::orbit
