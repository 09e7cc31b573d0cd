// A scan as it runs (docs/calibration.md): the order of the points, when a point is read (settled,
// still, for dwell_s of still time), which readings count, missed points, and the fit at the end.
#include "azt/calibration/scan_session.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

ScanSpec cross(std::size_t n) {
  ScanSpec spec;
  spec.beamwidth_deg = 1.0;
  spec.points_per_line = n;
  return spec;
}

TEST(ScanSession, ACrossGoesThereAndBackAlongEachLine) {
  const auto plan = plan_scan(cross(5)).value();
  const auto order = measuring_order(ScanKind::Cross, plan);
  ASSERT_EQ(order.size(), 20U);
  const double xs[] = {-2, -1, 0, 1, 2, 2, 1, 0, -1, -2};
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_DOUBLE_EQ(order[i].offset.xel_deg, xs[i]) << i;
    EXPECT_DOUBLE_EQ(order[i].offset.el_deg, 0.0) << i;
    EXPECT_DOUBLE_EQ(order[10 + i].offset.el_deg, xs[i]) << i;
  }
  ScanSpec raster = cross(5);
  raster.kind = ScanKind::Raster;
  const auto grid = plan_scan(raster).value();
  EXPECT_EQ(measuring_order(ScanKind::Raster, grid).size(), grid.size());
}

/// An antenna that reaches each offset `travel_s` after it is asked for, then stands still, and
/// a source of a 1° Gaussian beam at (0.2, −0.1) rising 3 dB.
struct Bench {
  double t = 0.0;
  double travel_s = 2.0;
  double arrived_at = 0.0;
  std::optional<SkyOffset> target;
  SkyOffset at{};

  static double power_db(const SkyOffset& o) {
    const double dx = o.xel_deg - 0.2, dy = o.el_deg + 0.1;
    return 10.0 * std::log10(1.0 + std::exp(-4.0 * std::log(2.0) * (dx * dx + dy * dy)));
  }

  /// Runs the session at 20 Hz with readings at 5 Hz; returns the readings that counted.
  int run(ScanSession& s, double limit_s = 1e5) {
    int counted = 0;
    for (int k = 0; !s.done() && t < limit_s; ++k) {
      const auto want = s.offset();
      if (!target || want->xel_deg != target->xel_deg || want->el_deg != target->el_deg) {
        target = want;
        arrived_at = t + travel_s;
      }
      const bool driving = t < arrived_at;
      if (!driving) at = *target;
      const control::AzEl encoders{at.xel_deg, at.el_deg};
      s.tick(t, driving, encoders, at);
      if (k % 4 == 0 && s.reading(t, power_db(at))) ++counted;
      t += 0.05;
    }
    return counted;
  }
};

TEST(ScanSession, ReadsEachPointAfterItSettlesAndFitsTheSource) {
  ScanTiming timing;
  timing.settle_s = 1.0;
  timing.dwell_s = 2.0;
  auto s = ScanSession::start(cross(9), timing, {}, 0.0);
  ASSERT_TRUE(s);
  Bench bench;
  const int counted = bench.run(s.value());
  ASSERT_TRUE(s->done());
  EXPECT_EQ(s->samples().size(), 36U);
  // Every point: 2 s of travel, 1 s settling, then 2 s of still time at 5 readings a second.
  EXPECT_NEAR(counted, 36 * 10, 36);
  EXPECT_NEAR(bench.t, 36 * 5.0, 36 * 0.2);
  for (const ScanSample& sample : s->samples()) {
    ASSERT_TRUE(sample.power_db);
    ASSERT_TRUE(sample.pointed);
  }
  const auto fit = s->fit();
  ASSERT_TRUE(fit) << fit.error().message;
  EXPECT_NEAR(fit->peak.xel_deg, 0.2, 1e-6);
  EXPECT_NEAR(fit->peak.el_deg, -0.1, 1e-6);
  // Each line's readings centre on its turn: the end of its first pass.
  ASSERT_TRUE(s->xel_moment_s());
  ASSERT_TRUE(s->el_moment_s());
  EXPECT_NEAR(*s->xel_moment_s(), 9 * 5.0, 2.0);
  EXPECT_NEAR(*s->el_moment_s(), 27 * 5.0, 4.0);
}

TEST(ScanSession, ReadingsWhileMovingOrSettlingDoNotCount) {
  auto s = ScanSession::start(cross(5), ScanTiming{}, {}, 0.0).value();
  s.tick(0.0, true, control::AzEl{1.0, 2.0}, SkyOffset{});
  EXPECT_FALSE(s.reading(0.0, 3.0));  // driving
  s.tick(0.05, false, control::AzEl{1.0, 2.0}, SkyOffset{});
  EXPECT_FALSE(s.reading(0.05, 3.0));  // not yet settled
  s.tick(1.2, false, control::AzEl{1.0, 2.0}, SkyOffset{});
  s.tick(1.3, false, control::AzEl{1.0, 2.0}, SkyOffset{});
  EXPECT_TRUE(s.reading(1.3, 3.0));
  EXPECT_FALSE(s.reading(1.3, std::nan("")));
  // The encoders move (a coast after the drive stopped): still no longer.
  s.tick(1.35, false, control::AzEl{1.01, 2.0}, SkyOffset{});
  EXPECT_FALSE(s.reading(1.35, 3.0));
}

TEST(ScanSession, APointNeverReachedIsMissedAndTheScanGoesOn) {
  ScanTiming timing;
  timing.max_settle_s = 10.0;
  auto s = ScanSession::start(cross(5), timing, {}, 0.0).value();
  for (double t = 0.0; t <= 10.5; t += 0.05) s.tick(t, true, control::AzEl{}, SkyOffset{});
  ASSERT_EQ(s.samples().size(), 1U);
  EXPECT_FALSE(s.samples()[0].power_db);
  EXPECT_EQ(s.points_done(), 1U);
  EXPECT_EQ(s.points_total(), 20U);
}

TEST(ScanSession, RefusesABadPlanOrTiming) {
  ScanSpec bad = cross(4);
  EXPECT_FALSE(ScanSession::start(bad, ScanTiming{}, {}, 0.0));
  ScanTiming timing;
  timing.dwell_s = 0.0;
  EXPECT_FALSE(ScanSession::start(cross(5), timing, {}, 0.0));
}

TEST(ScanSession, OffsetsAreAboutTheCentre) {
  auto s = ScanSession::start(cross(5), ScanTiming{}, SkyOffset{0.5, -0.25}, 0.0).value();
  EXPECT_DOUBLE_EQ(s.offset()->xel_deg, -1.5);
  EXPECT_DOUBLE_EQ(s.offset()->el_deg, -0.25);
}

}  // namespace
}  // namespace azt::calibration
