// The daemon's calibration session (docs/calibration.md "In the daemon") on an injected clock: the
// core's session and planner run through the station's scanner, each found scan's rows go to
// the log, the Sun waits its interval between scans, the session ends when its scans are in,
// a session resumed from its rows carries on from them, a stop or another command ends it, and
// the request is kept while it runs. The antenna is wherever it is asked half a second later;
// the receiver hears a 1.6° beam on a Sun that sits 0.1° of cross-elevation and −0.05° of
// elevation from where the ephemeris puts it.
#include "calibration/calibration_runner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "azt/calibration/pointing_model.hpp"
#include "calibration/pointing_history.hpp"
#include "calibration/scan_log_file.hpp"

namespace azt::app {
namespace {

constexpr double kEpochUnixS = 1764000000.0;  // 2025-11-24
constexpr double kBeamDeg = 1.6;
const calibration::SkyOffset kTrueOffset{0.1, -0.05};

control::AzEl sun_at(double t_s) { return {150.0 + 0.004 * t_s, 40.0}; }

CalibrationRequest request() {
  CalibrationRequest r;
  r.sources = {"Sun"};
  r.hours = 1.0;
  r.spec.kind = calibration::ScanKind::FivePoint;
  r.spec.beamwidth_deg = kBeamDeg;
  r.timing.settle_s = 0.5;
  r.timing.dwell_s = 1.0;
  r.sun_every_min = 1.0;
  r.refine = false;
  r.max_scans = 3;
  return r;
}

SessionSky sky() {
  SessionSky s;
  s.sources = {{"Sun", 99.0, 0.31, true}};
  s.at_unix = [](std::size_t, double unix_s) {
    return std::optional<control::AzEl>(sun_at(unix_s - kEpochUnixS));
  };
  return s;
}

struct Bench {
  calibration::PowerFeed feed;
  PointingScanner scanner{&feed};
  std::vector<calibration::ScanLogEntry> appended;
  std::vector<nlohmann::json> kept;
  std::vector<std::string> pointed;
  bool taken = false;  ///< the operator pointed the station elsewhere
  CalibrationRunner runner;
  double t = 0.0;
  control::AzEl at{150.0, 40.0};
  bool moving = false;
  double asked_at = 0.0;
  int k = 0;

  explicit Bench(std::vector<calibration::ScanLogEntry> log = {})
      : runner(scanner,
               {[this](const std::string& name) -> Result<std::string> {
                  pointed.push_back(name);
                  return name;
                },
                [this]() -> std::optional<std::string> {
                  if (taken) return std::string("Moon");
                  if (pointed.empty()) return std::nullopt;
                  return pointed.back();
                },
                [] { return control::PositionCorrections{}; },
                [this](const std::vector<calibration::ScanLogEntry>& rows) {
                  appended.insert(appended.end(), rows.begin(), rows.end());
                },
                [this](const nlohmann::json& r) { kept.push_back(r); }},
               std::move(log)) {}

  /// The power the beam at `beam` hears: a Gaussian beam on the displaced Sun, with a little
  /// deterministic scatter.
  double power_db(const control::AzEl& beam, double t_s) {
    const auto off =
        calibration::offset_between(calibration::apply_offset(sun_at(t_s), kTrueOffset), beam);
    const double d2 = off.xel_deg * off.xel_deg + off.el_deg * off.el_deg;
    const double rise = 100.0 * std::exp(-4.0 * std::log(2.0) * d2 / (kBeamDeg * kBeamDeg));
    return 10.0 * std::log10(1.0 + rise) + 0.01 * std::sin(1.7 * k);
  }

  void run_until(double until_s, std::size_t rows = 1000) {
    while (t < until_s && appended.size() < rows) {
      const control::AzEl source = sun_at(t);
      const auto want = scanner.aim(source).value_or(source);
      // A move of more than 0.02° takes half a second; smaller ones (the source's drift) are
      // followed at once. The encoders read in 0.01° steps.
      const double away = std::fabs(want.az_deg - at.az_deg) + std::fabs(want.el_deg - at.el_deg);
      if (away > 0.02 && !moving) {
        moving = true;
        asked_at = t;
      }
      if (moving && t - asked_at >= 0.5) moving = false;
      if (!moving) at = want;
      const bool driving = moving;
      const control::AzEl read{std::round(at.az_deg * 100.0) / 100.0,
                               std::round(at.el_deg * 100.0) / 100.0};
      if (k % 4 == 0) feed.accept(t, power_db(at, t));
      scanner.tick(t, driving, read, source, read);
      runner.tick(t);
      t += 0.05;
      ++k;
      if (!runner.running()) return;
    }
  }
};

TEST(CalibrationRunner, ThreeSunScansLandInTheLogAtTheirIntervalAndTheSessionEnds) {
  Bench b;
  b.feed.accept(0.0, 0.0);
  ASSERT_TRUE(b.runner.start(request(), sky(), 0.0, kEpochUnixS));
  ASSERT_EQ(b.kept.size(), 1u);
  EXPECT_EQ(b.kept[0]["request"]["max_scans"], 3);
  EXPECT_EQ(b.kept[0]["started_unix_s"], kEpochUnixS);
  EXPECT_EQ(b.runner.to_json()["state"], "running");
  EXPECT_EQ(b.runner.to_json()["scans_planned"], 3);
  b.run_until(3600.0);
  const nlohmann::json j = b.runner.to_json();
  EXPECT_EQ(j["state"], "done") << j.dump();
  EXPECT_EQ(j["scans_done"], 3);
  EXPECT_TRUE(j["current"].is_null());
  ASSERT_EQ(b.appended.size(), 3u);  // five-point scans: one row each
  EXPECT_EQ(j["log_rows"], 3);
  EXPECT_EQ(j["last_rows"].size(), 3u);
  for (std::size_t i = 0; i < b.appended.size(); ++i) {
    const calibration::ScanLogEntry& row = b.appended[i];
    const control::AzEl truth =
        calibration::apply_offset(sun_at(row.utc.unix_seconds() - kEpochUnixS), kTrueOffset);
    EXPECT_NEAR(row.az_deg + row.daz_deg, truth.az_deg, 0.01) << i;
    EXPECT_NEAR(row.el_deg + row.del_deg, truth.el_deg, 0.01) << i;
    EXPECT_EQ(row.source, "Sun");
    if (i > 0) {
      // Every minute, start to start: the rows (each at its scan's moment) a minute apart or more.
      EXPECT_GE(row.utc.unix_seconds() - b.appended[i - 1].utc.unix_seconds(), 50.0) << i;
    }
  }
  EXPECT_TRUE(b.kept.back().is_null()) << "the kept request is removed at the end";
  EXPECT_EQ(b.pointed.size(), 3u);
}

TEST(CalibrationRunner, AResumedSessionCountsItsRowsAndCarriesOn) {
  Bench first;
  first.feed.accept(0.0, 0.0);
  ASSERT_TRUE(first.runner.start(request(), sky(), 0.0, kEpochUnixS));
  first.run_until(3600.0, 1);
  ASSERT_EQ(first.appended.size(), 1u);
  // A restart: a new loop clock (0 again) at a later UTC, the log as the file kept it.
  const double restart_unix = kEpochUnixS + first.t + 5.0;
  Bench second(first.appended);
  second.t = 0.0;
  second.feed.accept(0.0, 0.0);
  ASSERT_TRUE(second.runner.start(request(), sky(), 0.0, restart_unix, kEpochUnixS));
  EXPECT_EQ(second.runner.to_json()["scans_done"], 1);
  EXPECT_EQ(second.runner.to_json()["log_rows"], 1);
  second.run_until(3600.0);
  EXPECT_EQ(second.runner.to_json()["state"], "done") << second.runner.to_json().dump();
  EXPECT_EQ(second.runner.to_json()["scans_done"], 3);
  EXPECT_EQ(second.appended.size(), 2u) << "two more scans, not three";
  EXPECT_EQ(second.runner.log().size(), 3u);
}

TEST(CalibrationRunner, AStopEndsTheScanAndTheSession) {
  Bench b;
  b.feed.accept(0.0, 0.0);
  ASSERT_TRUE(b.runner.start(request(), sky(), 0.0, kEpochUnixS));
  b.run_until(3.0);
  ASSERT_TRUE(b.scanner.running());
  EXPECT_EQ(b.runner.to_json()["current"]["source"], "Sun");
  EXPECT_EQ(b.runner.to_json()["current"]["kind"], "five-point");
  b.runner.stop("stopped by console");
  EXPECT_FALSE(b.scanner.running());
  EXPECT_EQ(b.runner.to_json()["state"], "stopped");
  EXPECT_EQ(b.runner.to_json()["reason"], "stopped by console");
  EXPECT_TRUE(b.kept.back().is_null());
  EXPECT_TRUE(b.appended.empty());
}

TEST(CalibrationRunner, AScanStoppedByAnotherCommandEndsTheSession) {
  Bench b;
  b.feed.accept(0.0, 0.0);
  ASSERT_TRUE(b.runner.start(request(), sky(), 0.0, kEpochUnixS));
  b.run_until(3.0);
  b.scanner.stop("stopped: the station was given another command");
  b.run_until(4.0);
  EXPECT_EQ(b.runner.to_json()["state"], "stopped");
  EXPECT_EQ(b.runner.to_json()["reason"], "stopped: the station was given another command");
}

TEST(CalibrationRunner, AnotherTargetBetweenScansEndsTheSessionWithoutTakingTheStationBack) {
  Bench b;
  b.feed.accept(0.0, 0.0);
  ASSERT_TRUE(b.runner.start(request(), sky(), 0.0, kEpochUnixS));
  b.run_until(3600.0, 1);  // the first scan is in; the next waits for the Sun's minute
  ASSERT_EQ(b.runner.to_json()["state"], "running");
  ASSERT_FALSE(b.scanner.running());
  b.taken = true;
  b.run_until(b.t + 120.0);
  EXPECT_EQ(b.runner.to_json()["state"], "stopped");
  EXPECT_EQ(b.runner.to_json()["reason"], "stopped: the station was given another command");
  EXPECT_EQ(b.pointed.size(), 1u) << "the session did not point the station again";
}

TEST(CalibrationRunner, ASilentReceiverIsWaitedForAMinuteThenTheSessionStops) {
  Bench b;  // no reading at all
  ASSERT_TRUE(b.runner.start(request(), sky(), 0.0, kEpochUnixS));
  for (double t = 0.0; t < 30.0; t += 0.5) b.runner.tick(t);
  EXPECT_EQ(b.runner.to_json()["state"], "running");
  for (double t = 30.0; t < 70.0; t += 0.5) b.runner.tick(t);
  EXPECT_EQ(b.runner.to_json()["state"], "stopped");
  EXPECT_NE(b.runner.to_json()["reason"].get<std::string>().find("silent"), std::string::npos)
      << b.runner.to_json()["reason"];
}

TEST(ScanLogFile, ABadRowCostsThatRowAloneAndIsNamed) {
  const std::string text =
      "utc,source,az_deg,el_deg,daz_deg,del_deg\n"
      "2025-11-20T17:00:00Z,sun,180,30,0.1,0.2\n"
      "2025-11-20T17:10:00Z,sun,180,abc,0.1,0.2\n"
      "# a comment\n"
      "2025-11-20T17:20:00Z,sun,182,31,0.1,0.2\n";
  const LoadedScanLog loaded = read_scan_log_file(text);
  ASSERT_EQ(loaded.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(loaded.rows[1].az_deg, 182.0);
  ASSERT_EQ(loaded.refused.size(), 1u);
  EXPECT_EQ(loaded.refused[0].rfind("line 3: ", 0), 0u) << loaded.refused[0];
  EXPECT_NE(loaded.refused[0].find("el"), std::string::npos) << loaded.refused[0];
  // What the daemon appends reads back.
  const std::string again = scan_log_lines(loaded.rows, true);
  EXPECT_EQ(read_scan_log_file(again).rows.size(), 2u);
  EXPECT_EQ(scan_log_lines(loaded.rows, false).find("utc"), std::string::npos);
}

TEST(PointingHistory, RecordsAreNumberedFoundAndListedNewestFirst) {
  std::size_t skipped = 0;
  PointingHistory h = PointingHistory::parse("not json\n", skipped);
  EXPECT_EQ(skipped, 1u);
  EXPECT_TRUE(h.empty());
  calibration::PointingTerms terms;
  terms.ia_deg = 0.5;
  h.add(h.record({}, std::nullopt, 0, "in use", "2025-11-20T17:00:00Z"));
  h.add(h.record(terms, 0.01, 12, "fit", "2025-11-20T18:00:00Z"));
  const nlohmann::json list = h.newest_first()["models"];
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["id"], 2);
  EXPECT_EQ(list[0]["why"], "fit");
  EXPECT_EQ(list[1]["rms_after_deg"], nullptr);
  ASSERT_NE(h.find(2), nullptr);
  EXPECT_DOUBLE_EQ(PointingHistory::terms_of(*h.find(2))->ia_deg, 0.5);
  EXPECT_EQ(h.find(3), nullptr);
  const PointingHistory again =
      PointingHistory::parse(list[1].dump() + "\n" + list[0].dump(), skipped);
  EXPECT_EQ(skipped, 0u);
  EXPECT_EQ(again.record({}, std::nullopt, 0, "restore", "")["id"], 3);
}

}  // namespace
}  // namespace azt::app
