// The daemon's noise measurement (docs/calibration.md "Sun noise and the figure of merit"): the
// demand is the source plus the measurement's offset, the receiver's readings reach it once
// each, the result and the expected value are shown and handed to the log, and a stop or a
// silent receiver is said so.
#include "station/noise_runner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace azt::app {
namespace {

calibration::NoisePlan plan() {
  calibration::NoisePlan p;
  p.beamwidth_deg = 1.0;
  p.offset_beams = 3.0;
  p.repeats = 2;
  return p;
}

calibration::ScanTiming timing() {
  calibration::ScanTiming t;
  t.settle_s = 0.5;
  t.dwell_s = 1.0;
  return t;
}

/// A source at az 180°, el 0° (so cross-elevation is azimuth), an antenna that is wherever it is
/// asked 1 s after being asked, and a receiver that reads 10 dB with the beam within 0.5° of the
/// source and 0 dB elsewhere, at 5 Hz.
struct Bench {
  calibration::PowerFeed feed;
  std::vector<nlohmann::json> logged;
  NoiseRunner runner{&feed, [this](nlohmann::json j) { logged.push_back(std::move(j)); }};
  double t = 0.0;
  std::optional<control::AzEl> asked;
  double asked_at = 0.0;
  control::AzEl at{180.0, 0.0};

  void run(double until_s) {
    const control::AzEl source{180.0, 0.0};
    for (int k = 0; runner.running() && t < until_s; ++k) {
      const auto want = runner.aim(source);
      if (want && (!asked || want->az_deg != asked->az_deg)) {
        asked = want;
        asked_at = t;
      }
      const bool driving = t - asked_at < 1.0;
      if (!driving) at = *asked;
      if (k % 4 == 0) feed.accept(t, std::fabs(at.az_deg - 180.0) < 0.5 ? 10.0 : 0.0);
      runner.tick(t, driving, driving ? control::AzEl{t, 0.0} : at, source);
      t += 0.05;
    }
  }
};

TEST(NoiseRunner, OnAndOffTheSourceThenTheYFactorIsShownAndLogged) {
  Bench b;
  b.feed.accept(0.0, 0.0);
  NoiseExpected expected{
      {1296.0, 10.0, 0.6, 50.0, 1.6},
      calibration::sun_at_band(calibration::solar_flux_at_band_sfu(100.0, 1296.0), 1296.0)};
  ASSERT_TRUE(b.runner.start("Sun", plan(), timing(), expected, 0.0));
  EXPECT_EQ(b.runner.to_json()["state"], "running");
  // First on the source, at the ephemeris.
  EXPECT_DOUBLE_EQ(b.runner.aim({180.0, 0.0})->az_deg, 180.0);
  b.run(100.0);
  ASSERT_FALSE(b.runner.running());
  const nlohmann::json j = b.runner.to_json();
  EXPECT_EQ(j["state"], "done") << j.dump();
  EXPECT_EQ(j["steps_done"], 4);
  EXPECT_EQ(j["steps"][1]["on"], false);
  EXPECT_EQ(j["steps"][1]["side"], 1);
  EXPECT_EQ(j["steps"][3]["side"], -1);
  EXPECT_NEAR(j["result"]["y_factor_db"].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(j["result"]["std_error_db"].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(j["result"]["pairs"], 2);
  ASSERT_EQ(j["result"]["pair_y_db"].size(), 2U);  // the scatter the console plots
  EXPECT_NEAR(j["result"]["pair_y_db"][0].get<double>(), 10.0, 1e-9);
  // Expected: 64.62 SFU at 1296 MHz (F10.7 100 scaled), a 0.70° disc in the 1.6° beam.
  EXPECT_NEAR(j["result"]["expected"]["flux_sfu"].get<double>(), 64.62, 0.01);
  ASSERT_EQ(b.logged.size(), 1U);
  EXPECT_EQ(b.logged[0], j["result"]);
  EXPECT_EQ(b.logged[0]["source"], "Sun");
  EXPECT_DOUBLE_EQ(b.logged[0]["el_deg"].get<double>(), 0.0);
}

TEST(NoiseRunner, TheOffPointingsAreThreeBeamwidthsAlongTheAzimuth) {
  Bench b;
  b.feed.accept(0.0, 0.0);
  ASSERT_TRUE(b.runner.start("Sun", plan(), timing(), std::nullopt, 0.0));
  std::vector<double> asked;
  const control::AzEl source{180.0, 0.0};
  for (int k = 0; b.runner.running() && k < 4000; ++k) {
    const double az = b.runner.aim(source)->az_deg;
    if (asked.empty() || asked.back() != az) asked.push_back(az);
    b.run(b.t + 0.05);
  }
  ASSERT_GE(asked.size(), 4U);
  EXPECT_NEAR(asked[0], 180.0, 1e-9);
  EXPECT_NEAR(asked[1], 183.0, 1e-9);
  EXPECT_NEAR(asked[2], 180.0, 1e-9);
  EXPECT_NEAR(asked[3], 177.0, 1e-9);
  EXPECT_FALSE(b.runner.to_json()["result"].contains("expected"));  // none asked for
}

TEST(NoiseRunner, AStopIsShownAndNothingLogged) {
  Bench b;
  b.feed.accept(0.0, 0.0);
  ASSERT_TRUE(b.runner.start("Moon", plan(), timing(), std::nullopt, 0.0));
  b.run(3.0);
  b.runner.stop("stopped by console");
  EXPECT_FALSE(b.runner.running());
  EXPECT_FALSE(b.runner.aim({180.0, 0.0}));
  const nlohmann::json j = b.runner.to_json();
  EXPECT_EQ(j["state"], "stopped");
  EXPECT_EQ(j["reason"], "stopped by console");
  EXPECT_TRUE(b.logged.empty());
}

TEST(NoiseRunner, NoReceiverOrASilentOneRefusesTheStart) {
  NoiseRunner none(nullptr, nullptr);
  EXPECT_EQ(none.start("Sun", plan(), timing(), std::nullopt, 0.0).error().message,
            "no receiver: set [receiver] to measure noise");
  calibration::PowerFeed feed;
  NoiseRunner silent(&feed, nullptr);
  EXPECT_EQ(silent.start("Sun", plan(), timing(), std::nullopt, 10.0).error().message,
            "the receiver is silent: no reading to measure with");
  EXPECT_EQ(silent.to_json()["state"], "idle");
}

}  // namespace
}  // namespace azt::app
