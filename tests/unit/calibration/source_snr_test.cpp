// Which sources a station can hear (docs/calibration.md): antenna temperatures from flux
// densities, the Y-factor, a scan point's SNR, and the threshold that decides what is offered.
#include "azt/calibration/source_snr.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "azt/calibration/noise_expectation.hpp"
#include "azt/calibration/noise_sources.hpp"

namespace azt::calibration {
namespace {

TEST(SourceSnr, PointSourceAntennaTemperatureIsEtaASOverTwoK) {
  // 1000 Jy on a 10 m dish at 60 %: 0.6 · 78.54 m² · 1e-23 W m⁻² Hz⁻¹ / (2 · 1.380649e-23 J/K).
  EXPECT_NEAR(point_antenna_k(1000.0, 10.0, 0.6), 17.066, 0.001);
  EXPECT_NEAR(point_antenna_k(2000.0, 10.0, 0.6), 2.0 * point_antenna_k(1000.0, 10.0, 0.6), 1e-12);
  EXPECT_NEAR(point_antenna_k(1000.0, 20.0, 0.6), 4.0 * point_antenna_k(1000.0, 10.0, 0.6), 1e-12);
}

TEST(SourceSnr, ASourceAsWideAsTheBeamCouplesHalf) {
  EXPECT_DOUBLE_EQ(beam_coupling(0.0, 1.6), 1.0);
  EXPECT_DOUBLE_EQ(beam_coupling(1.6, 1.6), 0.5);
  EXPECT_NEAR(beam_coupling(0.53, 1.6), 2.56 / (2.56 + 0.2809), 1e-12);
}

TEST(SourceSnr, TheQuietSunAtTwentyThreeCentimetres) {
  // A 0.53° disc at 170 000 K at 1296 MHz: 2kT·Ω·ν²/c² ≈ 5.9e5 Jy (59 solar flux units, the
  // quiet Sun's flux at 23 cm).
  const double jy = disc_flux_jy(170000.0, 0.53, 1296.0);
  EXPECT_NEAR(jy / 1e4, 59.0, 1.0);
}

TEST(SourceSnr, YFactorAndPointSnr) {
  const DishSetup dish{10.0, 0.6, 50.0, 1.6};
  const PointNoise noise{0.1, 20.0};
  // Cas A at 1296 MHz (1876 Jy): 32 K over 50 K of system noise, 2.1 dB.
  const SourceEstimate casa = estimate_source({"casa", 1876.0, 0.0}, dish, noise);
  EXPECT_NEAR(casa.antenna_k, 32.02, 0.01);
  EXPECT_NEAR(casa.rise_db, 10.0 * std::log10(1.0 + casa.antenna_k / 50.0), 1e-12);
  // One point's noise: (10^0.01 − 1)/√20 of T_sys.
  const double point = (std::pow(10.0, 0.01) - 1.0) / std::sqrt(20.0);
  EXPECT_NEAR(casa.snr_db, 10.0 * std::log10(casa.antenna_k / 50.0 / point), 1e-9);
  // Four times the readings: 3 dB more SNR, the same rise.
  const SourceEstimate longer = estimate_source({"casa", 1876.0, 0.0}, dish, {0.1, 80.0});
  EXPECT_NEAR(longer.snr_db - casa.snr_db, 10.0 * std::log10(2.0), 1e-9);
  EXPECT_DOUBLE_EQ(longer.rise_db, casa.rise_db);
}

TEST(SourceSnr, OffersOnlySourcesAboveTheThreshold) {
  const DishSetup dish{10.0, 0.6, 50.0, 1.6};
  const PointNoise noise{0.1, 20.0};
  std::vector<SourceEstimate> all;
  for (const SourceFlux& s : {SourceFlux{"casa", 1876.0, 0.0}, SourceFlux{"vira", 226.0, 0.0},
                              SourceFlux{"hera", 52.0, 0.0}}) {
    all.push_back(estimate_source(s, dish, noise));
  }
  const auto offered = worth_scanning(all, 10.0);
  ASSERT_EQ(offered.size(), 2U);  // Hercules A's 0.9 K is 5 dB over a point's noise
  EXPECT_EQ(offered[0].name, "casa");
  EXPECT_EQ(offered[1].name, "vira");
  EXPECT_LT(all[2].snr_db, 10.0);
  EXPECT_TRUE(worth_scanning(all, 40.0).empty());
}

TEST(SourceSnr, NothingToHearOrNoNoiseAreTheLimits) {
  const DishSetup dish;
  EXPECT_EQ(estimate_source("none", 0.0, 0.0, dish, {}).snr_db, -300.0);
  EXPECT_EQ(estimate_source("quiet", 10.0, 0.0, dish, {0.0, 20.0}).snr_db, 300.0);
}

TEST(SourceSnr, RadiometerEquation) {
  // 1 MHz for 1 s: ΔT/T = 1e-3, 0.0043 dB.
  EXPECT_NEAR(radiometer_noise_db(1e6, 1.0), 10.0 * std::log10(1.001), 1e-12);
}

}  // namespace
}  // namespace azt::calibration
