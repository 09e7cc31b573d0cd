// The fit of a drift scan (docs/calibration.md "Drift scans"): the beamwidth from the width in
// time and the source's rate, the offset along the path from the time of the peak, and the
// refusals. The bins are made from a known beam, path and pointing error, worked in the comments.
#include "azt/calibration/drift_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

/// A 1° beam whose true pointing is `error` off where the station believes it (true beam −
/// source = pointed + error), 900 K on 100 K, as the believed beam moves relative to the source
/// along `dir` at `rate` °/s, passing its closest believed point `cross` across at t = 750 s.
/// Bins every 2 s for 1500 s.
std::vector<DriftBin> drift(SkyOffset dir, double rate, SkyOffset error, double cross = 0.0) {
  std::vector<DriftBin> bins;
  for (double t = 1.0; t < 1500.0; t += 2.0) {
    const double along = rate * (t - 750.0);
    const SkyOffset pointed{along * dir.xel_deg - cross * dir.el_deg,
                            along * dir.el_deg + cross * dir.xel_deg};
    const double dx = pointed.xel_deg + error.xel_deg, dy = pointed.el_deg + error.el_deg;
    const double t_k = 100.0 + 900.0 * std::exp(-4.0 * std::log(2.0) * (dx * dx + dy * dy));
    bins.push_back({t, t_k / 100.0, pointed, 10});
  }
  return bins;
}

TEST(DriftFit, TheBeamwidthAndTheOffsetAlongAnAzimuthPath) {
  // Along +xel at 0.004 °/s, the true beam 0.1° further along than believed (and 0.05° up): the
  // power peaks when pointed + 0.1 = 0, at 750 − 0.1/0.004 = 725 s. Its width in time is
  // 1°/(0.004 °/s) = 250 s. The offset to add to the ephemeris is −0.1° along the path; the
  // 0.05° across it only lowers the peak.
  const auto f = fit_drift(drift({1.0, 0.0}, 0.004, {0.1, 0.05}), 1.0);
  ASSERT_TRUE(f) << f.error().message;
  EXPECT_NEAR(f->rate_deg_s, 0.004, 1e-12);
  EXPECT_NEAR(f->direction.xel_deg, 1.0, 1e-12);
  EXPECT_NEAR(f->peak_s, 725.0, 1e-4);
  EXPECT_NEAR(f->width_s, 250.0, 1e-4);
  EXPECT_NEAR(f->width_deg, 1.0, 1e-6);
  EXPECT_NEAR(f->along_offset_deg, -0.1, 1e-6);
  EXPECT_NEAR(f->offset().xel_deg, -0.1, 1e-6);
  EXPECT_NEAR(f->offset().el_deg, 0.0, 1e-12);
  EXPECT_NEAR(f->cross_track_deg, 0.0, 1e-9);
  // The peak: 900·e^(−4 ln2·0.05²) = 893.8 K over 100 K: 10·log10(9.938) = 9.973 dB.
  EXPECT_NEAR(f->peak_db, 9.973, 0.001);
  EXPECT_NEAR(f->noise_db, 0.0, 1e-6);
  EXPECT_EQ(f->used, 750U);
  // At 60° of elevation that is −0.1°/cos 60° = −0.2° of azimuth.
  EXPECT_NEAR(drift_az_offset_deg(*f, 60.0).value(), -0.2, 1e-6);
}

TEST(DriftFit, APathAtAnAngle) {
  // Along (0.6, 0.8) at 0.003 °/s, the error (0.1, −0.2): along the path e·u = 0.06 − 0.16 = −0.1,
  // so the offset found is +0.1 along it, (0.06, 0.08). The believed beam passes 0.2° to the left
  // of the source (cross = +0.2). Width 1°/0.003 = 333.33 s.
  const auto f = fit_drift(drift({0.6, 0.8}, 0.003, {0.1, -0.2}, 0.2), 1.0);
  ASSERT_TRUE(f) << f.error().message;
  EXPECT_NEAR(f->width_deg, 1.0, 1e-6);
  EXPECT_NEAR(f->width_s, 333.333, 1e-3);
  EXPECT_NEAR(f->along_offset_deg, 0.1, 1e-6);
  EXPECT_NEAR(f->offset().xel_deg, 0.06, 1e-6);
  EXPECT_NEAR(f->offset().el_deg, 0.08, 1e-6);
  EXPECT_NEAR(f->cross_track_deg, 0.2, 1e-6);
  // |u_xel| = 0.6 ≥ 0.5: the azimuth follows, 0.1/0.6 = 0.16667° of cross-elevation, at the
  // horizon as much azimuth. A path along the vertical says nothing of the azimuth.
  EXPECT_NEAR(drift_az_offset_deg(*f, 0.0).value(), 0.16667, 1e-5);
  const auto steep = fit_drift(drift({0.3, 0.953939}, 0.003, {0.0, 0.0}), 1.0);
  ASSERT_TRUE(steep);
  EXPECT_FALSE(drift_az_offset_deg(*steep, 30.0));
}

TEST(DriftFit, RefusalsSayWhy) {
  auto bins = drift({1.0, 0.0}, 0.004, {});
  bins.resize(10);
  EXPECT_EQ(fit_drift(bins, 1.0).error().message,
            "too few readings: 10 intervals (at least 15 needed)");
  // A source that does not move.
  EXPECT_EQ(fit_drift(drift({1.0, 0.0}, 0.0, {}), 1.0).error().message,
            "the source did not drift across the beam");
  // Nothing in the beam: flat power with a little ripple.
  auto flat = drift({1.0, 0.0}, 0.004, {});
  for (std::size_t i = 0; i < flat.size(); ++i)
    flat[i].power = 1.0 + 0.001 * std::sin(static_cast<double>(i) * 1.3);
  const auto none = fit_drift(flat, 1.0);
  ASSERT_FALSE(none);
  // A beam four times wider than expected.
  const auto f = fit_drift(drift({1.0, 0.0}, 0.004, {}), 0.25);
  ASSERT_FALSE(f);
  EXPECT_EQ(f.error().message, "the fitted width is not within 0.3–3 beamwidths");
}

TEST(DriftFit, TheSiderealRate) {
  // 360°/86164.0905 s = 0.0041781 °/s on the equator; Cygnus A at δ = 40.7339°: × cos δ =
  // 0.0031659 °/s.
  EXPECT_NEAR(sidereal_drift_rate_deg_s(0.0), 0.0041781, 1e-7);
  EXPECT_NEAR(sidereal_drift_rate_deg_s(40.7339), 0.0031659, 1e-7);
}

}  // namespace
}  // namespace azt::calibration
