// A drift scan as it runs (docs/calibration.md "Drift scans"): when the source reaches the held
// point, when the recording starts and ends, the readings binned, the fit, and the refusals.
#include "azt/calibration/drift_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

DriftSpec spec() {
  DriftSpec s;
  s.beamwidth_deg = 1.0;
  s.ahead_beams = 3.0;
  s.slew_s = 60.0;
  s.settle_s = 2.0;
  s.bin_s = 2.0;
  return s;
}

/// An antenna that reaches the held point `travel_s` after the start and stands still there,
/// and a source drifting through it along −xel at `rate` °/s (the beam relative to the source,
/// pointed, grows; the session is given the source relative to the beam, its negative),
/// reaching it at `transit_s`. The true beam is `error_deg` further along than believed. 900 K
/// on 100 K; the controller ticks at 20 Hz, the receiver reads at 5 Hz.
struct Bench {
  double travel_s = 30.0;
  double rate = 0.004;
  double error_deg = 0.0;

  int run(DriftScan& d) {
    int counted = 0;
    double t = 0.0;
    for (int k = 0; !d.done() && t < 1e5; ++k) {
      const bool driving = t < travel_s;
      const SkyOffset pointed{rate * (t - d.transit_s()), 0.0};
      const control::AzEl enc = driving ? control::AzEl{t, 0.0} : control::AzEl{1.0, 2.0};
      d.tick(t, driving, enc, SkyOffset{-pointed.xel_deg, 0.0});
      const double x = pointed.xel_deg + error_deg;
      const double t_k = 100.0 + 900.0 * std::exp(-4.0 * std::log(2.0) * x * x);
      if (k % 4 == 0 && d.reading(t, 10.0 * std::log10(t_k / 100.0))) ++counted;
      t += 0.05;
    }
    return counted;
  }
};

TEST(DriftScan, HoldsAheadOfTheSourceAndRecordsItsPassage) {
  // Three beamwidths at 0.004 °/s: 750 s of lead. The transit is the slew's allowance (60 s) and
  // the lead after the start: 810 s; the recording ends 750 s later, at 1560 s.
  auto d = DriftScan::start(spec(), 0.004, 0.0);
  ASSERT_TRUE(d) << d.error().message;
  EXPECT_DOUBLE_EQ(d->transit_s(), 810.0);
  EXPECT_DOUBLE_EQ(d->end_s(), 1560.0);
  EXPECT_EQ(d->phase(), DriftPhase::Slewing);
  Bench bench;
  bench.error_deg = 0.1;
  const int counted = bench.run(d.value());
  ASSERT_EQ(d->phase(), DriftPhase::Done);
  // Recording from 32 s (30 s of travel, 2 s settling) to 1560 s at 5 readings a second.
  EXPECT_NEAR(counted, (1560 - 32) * 5, 10);
  EXPECT_NEAR(static_cast<double>(d->bins().size()), (1560.0 - 32.0) / 2.0, 2.0);
  const auto f = d->fit();
  ASSERT_TRUE(f) << f.error().message;
  EXPECT_NEAR(f->width_deg, 1.0, 1e-4);
  EXPECT_NEAR(f->rate_deg_s, 0.004, 1e-9);
  // The true beam 0.1° further along: the peak 25 s before the transit, and the offset −0.1°.
  EXPECT_NEAR(f->peak_s, 785.0, 0.05);
  EXPECT_NEAR(f->along_offset_deg, -0.1, 2e-4);
}

TEST(DriftScan, ReadingsBeforeTheAntennaStandsStillDoNotCount) {
  auto started = DriftScan::start(spec(), 0.004, 0.0);
  DriftScan& d = started.value();
  EXPECT_FALSE(d.reading(0.0, 1.0));  // slewing
  d.tick(0.0, true, control::AzEl{0.0, 0.0}, SkyOffset{});
  d.tick(0.05, false, control::AzEl{1.0, 0.0}, SkyOffset{});
  // The encoders changed at 0.05 s; unchanged from 1 s on: still since then.
  d.tick(1.0, false, control::AzEl{1.0, 0.0}, SkyOffset{});
  d.tick(2.9, false, control::AzEl{1.0, 0.0}, SkyOffset{});
  EXPECT_EQ(d.phase(), DriftPhase::Slewing);  // still 1.9 s, not the 2 s of settle_s
  d.tick(3.05, false, control::AzEl{1.0, 0.0}, SkyOffset{});
  EXPECT_EQ(d.phase(), DriftPhase::Recording);
  EXPECT_TRUE(d.reading(3.05, 1.0));
  EXPECT_FALSE(d.reading(3.1, NAN));
  // Without a position the reading is not placed, so it does not count.
  d.tick(3.15, false, control::AzEl{1.0, 0.0}, std::nullopt);
  EXPECT_FALSE(d.reading(3.2, 1.0));
  EXPECT_EQ(d.fit().error().message, "the drift has not finished");
}

TEST(DriftScan, AnAntennaTooLateOnThePointFails) {
  // The point must be held while the source is still 1.5 beamwidths away: by 810 − 375 = 435 s.
  auto d = DriftScan::start(spec(), 0.004, 0.0);
  Bench bench;
  bench.travel_s = 500.0;
  bench.run(d.value());
  EXPECT_EQ(d->phase(), DriftPhase::Failed);
  EXPECT_EQ(d->fit().error().message,
            "the antenna did not stand still on the point in time: the source was already within "
            "1.5 beamwidths of it");
}

TEST(DriftScan, BadSpecsAreRefusedNamingTheField) {
  const auto refused = [](DriftSpec s, double rate, const char* field) {
    const auto d = DriftScan::start(s, rate, 0.0);
    ASSERT_FALSE(d) << field;
    EXPECT_NE(d.error().message.find(field), std::string::npos) << d.error().message;
  };
  DriftSpec s = spec();
  s.beamwidth_deg = 31.0;
  refused(s, 0.004, "beamwidth_deg");
  s = spec();
  s.ahead_beams = 1.0;
  refused(s, 0.004, "ahead_beams");
  s = spec();
  s.bin_s = 0.1;
  refused(s, 0.004, "bin_s");
  s = spec();
  s.settle_s = -1.0;
  refused(s, 0.004, "settle_s");
  s = spec();
  s.slew_s = NAN;
  refused(s, 0.004, "slew_s");
  refused(spec(), 0.0, "rate");
  // Polaris drifts at 0.0042·cos 89.26° = 5.4e-5 °/s: 3 beamwidths ahead is 15 h away.
  s = spec();
  const auto slow = DriftScan::start(s, 5.4e-5, 0.0);
  ASSERT_FALSE(slow);
  EXPECT_EQ(slow.error().message,
            "the source drifts too slowly: the drift would take 1853 minutes (at most 240)");
}

}  // namespace
}  // namespace azt::calibration
