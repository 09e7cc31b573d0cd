// The exact pointing geometry (docs/calibration.md) against the first-order sums each term is
// documented by, the inverse against the forward model, and the reading near the zenith and over
// it.
#include "azt/calibration/pointing_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace azt::calibration {
namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

double wrap_180(double d) { return std::remainder(d, 360.0); }

struct FirstOrder {
  double a_minus_A;
  double e_minus_E;
};

/// The sums documented in pointing_model.hpp for sky direction (A, E); written from the header's
/// comments, not from the code.
FirstOrder documented(const PointingTerms& t, double az_deg, double el_deg) {
  const double A = az_deg * kRadPerDeg, E = el_deg * kRadPerDeg;
  return {t.ia_deg - t.ca_deg / std::cos(E) + t.npae_deg * std::tan(E) +
              t.an_deg * std::sin(A) * std::tan(E) - t.aw_deg * std::cos(A) * std::tan(E),
          t.ie_deg + t.an_deg * std::cos(A) + t.aw_deg * std::sin(A) + t.sag_deg * std::cos(E)};
}

TEST(PointingModel, EachTermActsAsItsFirstOrderSum) {
  const double small = 0.01;  // second-order terms are then ~1e-6°
  for (int term = 0; term < PointingTerms::kCount; ++term) {
    std::array<double, PointingTerms::kCount> v{};
    v.at(static_cast<std::size_t>(term)) = small;
    const PointingTerms t = PointingTerms::from_array(v);
    for (const double az : {20.0, 110.0, 200.0, 290.0}) {
      for (const double el : {10.0, 45.0, 70.0}) {
        const auto mount = mount_for_sky({az, el}, t);
        ASSERT_TRUE(mount);
        const FirstOrder expect = documented(t, az, el);
        EXPECT_NEAR(wrap_180(mount->az_deg - az), expect.a_minus_A, 2e-5)
            << term << " " << az << " " << el;
        EXPECT_NEAR(mount->el_deg - el, expect.e_minus_E, 2e-5) << term << " " << az << " " << el;
      }
    }
  }
}

TEST(PointingModel, TiltTowardsAnAzimuthSplitsIntoAnAndAw) {
  const PointingTerms north = tilt_terms(0.5, 0.0), east = tilt_terms(0.5, 90.0);
  EXPECT_NEAR(north.an_deg, 0.5, 1e-15);
  EXPECT_NEAR(north.aw_deg, 0.0, 1e-15);
  EXPECT_NEAR(east.an_deg, 0.0, 1e-15);
  EXPECT_NEAR(east.aw_deg, 0.5, 1e-15);
  // A tilted axis lowers the beam on the side it leans to and raises it opposite.
  const control::AzEl toward = beam_on_sky({90.0, 30.0}, east);
  const control::AzEl away = beam_on_sky({270.0, 30.0}, east);
  EXPECT_NEAR(toward.el_deg, 29.5, 1e-6);
  EXPECT_NEAR(away.el_deg, 30.5, 1e-6);
}

TEST(PointingModel, InverseUndoesTheForwardModelWithDegreeSizedTerms) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> term(-1.0, 1.0), az(0.0, 360.0), el(2.0, 85.0);
  for (int i = 0; i < 500; ++i) {
    std::array<double, PointingTerms::kCount> v{};
    for (double& x : v) x = term(rng);
    const PointingTerms t = PointingTerms::from_array(v);
    const control::AzEl sky{az(rng), el(rng)};
    const auto mount = mount_for_sky(sky, t);
    ASSERT_TRUE(mount);
    EXPECT_LT(separation_deg(beam_on_sky(*mount, t), sky), 1e-8);
  }
}

TEST(PointingModel, ZeroTermsChangeNothing) {
  const PointingTerms none;
  EXPECT_TRUE(none.is_zero());
  const control::AzEl r = corrected_reading({123.4, 56.7}, none);
  EXPECT_DOUBLE_EQ(r.az_deg, 123.4);
  EXPECT_DOUBLE_EQ(r.el_deg, 56.7);
  const control::AzEl b = beam_on_sky({123.4, 56.7}, none);
  EXPECT_NEAR(b.az_deg, 123.4, 1e-12);
  EXPECT_NEAR(b.el_deg, 56.7, 1e-12);
}

TEST(PointingModel, AFlipMountsReadingStaysInItsFrame) {
  // Encoders at az 10°, el 120° look over the zenith at az 190°, el 60°: the corrected reading
  // stays near (10°, 120°), moved by the terms, not turned into the sky's (190°, 60°).
  PointingTerms t;
  t.ie_deg = 0.2;
  const control::AzEl r = corrected_reading({10.0, 120.0}, t);
  EXPECT_NEAR(r.az_deg, 10.0, 1e-9);
  EXPECT_NEAR(r.el_deg, 119.8, 1e-9);
}

TEST(PointingModel, NearTheZenithTheAzimuthCorrectionIsHeld) {
  // With a tilt, the beam's sky azimuth swings wildly close to the zenith; the reading's does
  // not: it keeps the correction found 5° from the zenith, while the elevation stays exact.
  const PointingTerms t = tilt_terms(0.3, 45.0);
  const control::AzEl held = corrected_reading({100.0, 85.0}, t);
  for (const double el : {86.0, 88.0, 89.9, 90.0}) {
    const control::AzEl r = corrected_reading({100.0, el}, t);
    EXPECT_NEAR(r.az_deg - 100.0, held.az_deg - 100.0, 1e-12) << el;
    const control::AzEl beam = beam_on_sky({100.0, el}, t);
    EXPECT_NEAR(std::min(r.el_deg, 180.0 - r.el_deg), beam.el_deg, 1e-9) << el;
  }
}

TEST(PointingModel, OffsetsAreTangentPlaneCoordinates) {
  const control::AzEl source{200.0, 60.0};
  // Small offsets are ΔA·cos E and ΔE.
  const control::AzEl near = apply_offset(source, {0.01, -0.005});
  EXPECT_NEAR(near.az_deg, 200.02, 1e-5);
  EXPECT_NEAR(near.el_deg, 59.995, 1e-5);
  // Along the tangent plane's axes the offset is the great-circle distance itself.
  const control::AzEl across = apply_offset(source, {2.0, 0.0});
  EXPECT_NEAR(separation_deg(source, across), 2.0, 1e-9);
  const control::AzEl up = apply_offset(source, {0.0, -3.0});
  EXPECT_NEAR(up.az_deg, 200.0, 1e-9);
  EXPECT_NEAR(up.el_deg, 57.0, 1e-9);
  // Near the zenith a cross-elevation line stays a line: 2° across is 2° away, not 2°/cos E of
  // azimuth along a circle of constant elevation.
  const control::AzEl high{10.0, 86.0};
  EXPECT_NEAR(separation_deg(high, apply_offset(high, {2.0, 0.0})), 2.0, 1e-9);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> az(0.0, 360.0), el(0.0, 89.0), off(-5.0, 5.0);
  for (int i = 0; i < 200; ++i) {
    const control::AzEl s{az(rng), el(rng)};
    const SkyOffset o{off(rng), off(rng)};
    const SkyOffset back = offset_between(s, apply_offset(s, o));
    EXPECT_NEAR(back.xel_deg, o.xel_deg, 1e-9);
    EXPECT_NEAR(back.el_deg, o.el_deg, 1e-9);
  }
  EXPECT_NEAR(separation_deg({0.0, 0.0}, {90.0, 0.0}), 90.0, 1e-12);
  EXPECT_NEAR(separation_deg({10.0, 89.0}, {190.0, 89.0}), 2.0, 1e-9);
}

}  // namespace
}  // namespace azt::calibration
