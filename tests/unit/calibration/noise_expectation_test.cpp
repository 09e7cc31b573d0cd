// The Y-factor a station should see (docs/calibration.md "Sun noise and the figure of merit"):
// the antenna temperature from flux and dish, the source-size correction, Y, and the figure of
// merit read back from a measured Y. Each expected value is worked by hand in its comment.
#include "azt/calibration/noise_expectation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

TEST(NoiseExpectation, SizeCorrections) {
  EXPECT_DOUBLE_EQ(size_correction(SourceShape::Point, 0.5, 1.0), 1.0);
  // A disc as wide as the beam: x² = ln2 = 0.69315, K = 0.69315/(1 − e^−0.69315) = 0.69315/0.5
  // = 1.38629.
  EXPECT_NEAR(size_correction(SourceShape::UniformDisc, 1.0, 1.0), 1.38629, 1e-5);
  // A small disc: K = 1 + x²/2 + x⁴/12 + …; θ/W = 0.1 gives x² = 0.0069315 and
  // 1 + 0.0034657 + 0.0000040 = 1.0034697.
  EXPECT_NEAR(size_correction(SourceShape::UniformDisc, 0.1, 1.0), 1.0034697, 1e-7);
  EXPECT_DOUBLE_EQ(size_correction(SourceShape::UniformDisc, 0.0, 1.0), 1.0);
  // The simulated Sun, a Gaussian 0.53° wide in a 1.6° beam: 1 + (0.53/1.6)² = 1.10973.
  EXPECT_NEAR(size_correction(SourceShape::Gaussian, 0.53, 1.6), 1.10973, 1e-5);
}

TEST(NoiseExpectation, ASunNoiseWorkedThrough) {
  // A 3 m dish of 60 % efficiency at 10368 MHz, T_sys 120 K, the Sun at 300 SFU on the band:
  //   λ = c/f = 0.0289152 m; beam 70λ/D = 0.674687°;
  //   the disc of 0.55°: x² = ln2·(0.55/0.674687)² = 0.460623, K = x²/(1 − e^−x²) = 1.247931;
  //   A = π·3²/4 = 7.068583 m²; a point source would give η·A·S/(2k)
  //     = 0.6·7.068583·3e-20/(2·1.380649e-23) = 4607.78 K; the disc 4607.78/1.247931 = 3692.34 K;
  //   Y = 10·log10(1 + 3692.34/120) = 15.0201 dB.
  NoiseStation st{10368.0, 3.0, 0.6, 120.0, 0.0};
  const auto e = expected_noise(st, sun_at_band(300.0, 10368.0));
  ASSERT_TRUE(e) << e.error().message;
  EXPECT_NEAR(e->beamwidth_deg, 0.674687, 1e-6);
  EXPECT_NEAR(e->size_factor, 1.247931, 1e-6);
  EXPECT_NEAR(point_antenna_k(3e6, 3.0, 0.6), 4607.78, 0.01);
  EXPECT_NEAR(e->antenna_k, 3692.34, 0.01);
  EXPECT_NEAR(e->y_db, 15.0201, 0.0001);
  // Read back: G/T = 8πk(Y − 1)K/(Sλ²) = 27.2526 dB/K, which is the dish's gain
  // 10·log10(η·4πA/λ²) = 48.0444 dBi less 10·log10(120 K) = 20.7918 dB.
  EXPECT_NEAR(g_over_t_db(e->y_db, e->flux_jy, 10368.0, e->size_factor), 27.2526, 0.0001);
  // And the system temperature the measured Y says is the one put in.
  EXPECT_NEAR(implied_tsys_k(e->y_db, e->antenna_k), 120.0, 1e-9);
}

TEST(NoiseExpectation, OwenDuffysCrossCheck) {
  // G/T of 12.22 dB/K and 106 SFU at 1296 MHz (a point source: K = 1) give Y = 14.51 dB
  // (https://owenduffy.net/blog/?p=1526 states 14.49 dB): Y − 1 = G/T·S·λ²/(8πk) =
  // 16.672·1.06e-20·0.053509/(8π·1.380649e-23) = 27.24.
  const double y_db =
      10.0 * std::log10(1.0 + std::pow(10.0, 1.222) * 1.06e-20 * std::pow(299792458.0 / 1296e6, 2) /
                                  (8.0 * 3.14159265358979 * 1.380649e-23));
  EXPECT_NEAR(y_db, 14.51, 0.005);
  EXPECT_NEAR(g_over_t_db(y_db, 1.06e6, 1296.0, 1.0), 12.22, 1e-9);
}

TEST(NoiseExpectation, MoonNoiseOfASmallDishAtTenGigahertz) {
  // 220 K, 0.5°: 43458 Jy (noise_sources_test). K = 1.202388 for the 0.674687° beam; η·A·S/(2k)
  // = 66.748 K, over K 55.513 K; Y = 10·log10(1 + 55.513/120) = 1.6513 dB (the 1.6 dB EME tables
  // give a 3 m dish at 10 GHz).
  const auto e = expected_noise({10368.0, 3.0, 0.6, 120.0, 0.0}, moon_at_band(220.0, 0.5, 10368.0));
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->antenna_k, 55.513, 0.001);
  EXPECT_NEAR(e->y_db, 1.6513, 0.0001);
}

TEST(NoiseExpectation, AGivenBeamwidthIsUsed) {
  NoiseStation st{1296.0, 10.0, 0.6, 50.0, 1.6};
  const auto e = expected_noise(st, {1e6, SourceShape::Gaussian, 0.53});
  ASSERT_TRUE(e);
  EXPECT_DOUBLE_EQ(e->beamwidth_deg, 1.6);
  EXPECT_NEAR(e->size_factor, 1.10973, 1e-5);
}

TEST(NoiseExpectation, BadStationsAreRefusedNamingTheField) {
  const SourceAtBand sun = sun_at_band(100.0, 1296.0);
  const auto refused = [&sun](NoiseStation st, const char* field) {
    const auto e = expected_noise(st, sun);
    ASSERT_FALSE(e) << field;
    EXPECT_NE(e.error().message.find(field), std::string::npos) << e.error().message;
  };
  refused({0.0, 3.0, 0.6, 50.0, 0.0}, "freq_mhz");
  refused({1296.0, -1.0, 0.6, 50.0, 0.0}, "dish_m");
  refused({1296.0, 3.0, 1.2, 50.0, 0.0}, "efficiency");
  refused({1296.0, 3.0, 0.6, NAN, 0.0}, "tsys_k");
  refused({1296.0, 3.0, 0.6, 50.0, 45.0}, "beamwidth_deg");
  const auto e = expected_noise({1296.0, 3.0, 0.6, 50.0, 0.0}, {-5.0, SourceShape::Point, 0.0});
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().message.find("flux"), std::string::npos);
}

TEST(NoiseExpectation, NoRiseSaysNothingFinite) {
  EXPECT_TRUE(std::isinf(implied_tsys_k(0.0, 100.0)));
  EXPECT_TRUE(std::isinf(g_over_t_db(-0.1, 1e6, 1296.0, 1.0)));
}

}  // namespace
}  // namespace azt::calibration
