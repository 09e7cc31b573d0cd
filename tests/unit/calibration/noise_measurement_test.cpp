// A noise measurement as it runs (docs/calibration.md "Sun noise and the figure of merit"): the
// order of the pointings, when each is read (point_dwell), the Y-factor of the pairs with its
// standard error, and the refusals. Worked by hand in the comments.
#include "azt/calibration/noise_measurement.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

NoisePlan plan(std::size_t repeats) {
  NoisePlan p;
  p.beamwidth_deg = 1.0;
  p.offset_beams = 3.0;
  p.repeats = repeats;
  return p;
}

ScanTiming timing() {
  ScanTiming t;
  t.settle_s = 1.0;
  t.dwell_s = 2.0;
  t.max_settle_s = 30.0;
  return t;
}

/// An antenna that reaches each offset `travel_s` after it is asked for, then stands still, over
/// a source of 900 K in a 1° beam on 100 K of system noise (on the source: 10·log10(1000/100) =
/// 10 dB), with the sky `gradient_db` warmer per degree towards increasing azimuth. While the
/// antenna moves it reads 30 dB (a reading that must not count).
struct Bench {
  double t = 0.0;
  double travel_s = 2.0;
  double arrived_at = 0.0;
  double gradient_db = 0.0;
  bool never_arrives = false;
  std::optional<SkyOffset> target;

  [[nodiscard]] double power_db(const SkyOffset& o) const {
    const double d2 = o.xel_deg * o.xel_deg + o.el_deg * o.el_deg;
    const double t_k = 100.0 + 900.0 * std::exp(-4.0 * std::log(2.0) * d2);
    return 10.0 * std::log10(t_k / 100.0) + gradient_db * o.xel_deg;
  }

  /// Runs at 20 Hz with readings at 5 Hz; returns the readings that counted.
  int run(NoiseMeasurement& m, double limit_s = 1e4) {
    int counted = 0;
    for (int k = 0; !m.done() && t < limit_s; ++k) {
      const auto want = m.offset();
      if (!target || want->xel_deg != target->xel_deg || want->el_deg != target->el_deg) {
        target = want;
        arrived_at = never_arrives ? 1e9 : t + travel_s;
      }
      const bool driving = t < arrived_at;
      // The encoders change while the antenna moves, and stand still once it is there.
      const control::AzEl enc =
          driving ? control::AzEl{t, 0.0} : control::AzEl{target->xel_deg, 0.0};
      m.tick(t, driving, enc);
      if (k % 4 == 0 && m.reading(driving ? 30.0 : power_db(*target))) ++counted;
      t += 0.05;
    }
    return counted;
  }
};

TEST(NoiseMeasurement, OnThenOffOnAlternateSides) {
  auto m = NoiseMeasurement::start(plan(3), timing(), 0.0);
  ASSERT_TRUE(m);
  const auto& s = m->steps();
  ASSERT_EQ(s.size(), 6U);
  const double xel[] = {0.0, 3.0, 0.0, -3.0, 0.0, 3.0};
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(s[i].on, i % 2 == 0) << i;
    EXPECT_DOUBLE_EQ(s[i].offset.xel_deg, xel[i]) << i;
    EXPECT_DOUBLE_EQ(s[i].offset.el_deg, 0.0) << i;
  }
  EXPECT_EQ(s[1].side, 1);
  EXPECT_EQ(s[3].side, -1);
  // The on-source pointing is where a scan found the beam on the source; the offs are about it.
  NoisePlan peaked = plan(2);
  peaked.centre = {0.1, -0.2};
  auto p = NoiseMeasurement::start(peaked, timing(), 0.0);
  ASSERT_TRUE(p);
  EXPECT_DOUBLE_EQ(p->offset()->xel_deg, 0.1);
  EXPECT_DOUBLE_EQ(p->steps()[1].offset.xel_deg, 3.1);
  EXPECT_DOUBLE_EQ(p->steps()[3].offset.el_deg, -0.2);
}

TEST(NoiseMeasurement, TheYFactorOfAQuietSky) {
  auto m = NoiseMeasurement::start(plan(4), timing(), 0.0);
  ASSERT_TRUE(m);
  Bench bench;
  const int counted = bench.run(m.value());
  ASSERT_TRUE(m->done());
  // Each pointing: 2 s of travel, 1 s settling, then 2 s of still time at 5 readings a second
  // (10 readings, give or take the one at either edge).
  EXPECT_NEAR(counted, 8 * 10, 8);
  for (const NoiseStep& step : m->steps()) EXPECT_NEAR(step.readings, 10, 1);
  const auto r = m->result();
  ASSERT_TRUE(r) << r.error().message;
  // On: 10 dB. Off at 3 beamwidths: 100 + 900·e^(−4 ln2·9) = 100 + 900·1.46e-11 K: 0.0000 dB.
  EXPECT_NEAR(r->y_db, 10.0, 1e-9);
  EXPECT_NEAR(r->std_error_db, 0.0, 1e-9);
  EXPECT_NEAR(r->on_db, 10.0, 1e-9);
  EXPECT_NEAR(r->off_db, 0.0, 1e-9);
  EXPECT_EQ(r->pair_y_db.size(), 4U);
  EXPECT_EQ(r->missed, 0U);
}

TEST(NoiseMeasurement, AlternatingSidesCancelASkyGradient) {
  // The sky 1/60 dB per degree warmer towards increasing azimuth: the off pointing at +3° reads
  // +0.05 dB, the one at −3° −0.05 dB. The pairs are 9.95, 10.05, 9.95, 10.05 dB: the mean is
  // 10 dB; their standard deviation √(4·0.05²/3) = 0.057735 over √4 is 0.028868 dB.
  auto m = NoiseMeasurement::start(plan(4), timing(), 0.0);
  Bench bench;
  bench.gradient_db = 0.05 / 3.0;
  bench.run(m.value());
  const auto r = m->result();
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->pair_y_db[0], 9.95, 1e-9);
  EXPECT_NEAR(r->pair_y_db[1], 10.05, 1e-9);
  EXPECT_NEAR(r->y_db, 10.0, 1e-9);
  EXPECT_NEAR(r->std_error_db, 0.028868, 1e-6);
}

TEST(NoiseMeasurement, ReadingsWhileTheAntennaMovesDoNotCount) {
  auto m = NoiseMeasurement::start(plan(2), timing(), 0.0);
  // The bench reads 30 dB while driving: one counted would spoil the 10 dB.
  Bench bench;
  bench.travel_s = 6.0;
  bench.run(m.value());
  EXPECT_NEAR(m->result()->y_db, 10.0, 1e-9);
  EXPECT_FALSE(m.value().reading(5.0));  // done: nothing counts
}

TEST(NoiseMeasurement, PointingsNeverReachedAreMissedAndTheResultRefused) {
  auto m = NoiseMeasurement::start(plan(2), timing(), 0.0);
  Bench bench;
  bench.never_arrives = true;
  bench.run(m.value());
  ASSERT_TRUE(m->done());  // each pointing given up after max_settle_s (30 s): 4 of them
  EXPECT_NEAR(bench.t, 4 * 30.0, 1.0);
  const auto r = m->result();
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().message,
            "too few on/off pairs read: 0 of 2 (4 pointings missed; at least 2 needed)");
}

TEST(NoiseMeasurement, BadPlansAreRefusedNamingTheField) {
  const auto refused = [](NoisePlan p, ScanTiming t, const char* field) {
    const auto m = NoiseMeasurement::start(p, t, 0.0);
    ASSERT_FALSE(m) << field;
    EXPECT_NE(m.error().message.find(field), std::string::npos) << m.error().message;
  };
  NoisePlan p = plan(4);
  p.beamwidth_deg = 0.0;
  refused(p, timing(), "beamwidth_deg");
  p = plan(4);
  p.offset_beams = 1.5;
  refused(p, timing(), "offset_beams");
  refused(plan(1), timing(), "repeats");
  refused(plan(51), timing(), "repeats");
  p = plan(4);
  p.centre.xel_deg = NAN;
  refused(p, timing(), "centre");
  ScanTiming t = timing();
  t.dwell_s = 0.0;
  refused(plan(4), t, "dwell_s");
}

}  // namespace
}  // namespace azt::calibration
