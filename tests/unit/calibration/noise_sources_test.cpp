// The noise sources at the band (docs/calibration.md "Sun noise and the figure of merit"): the
// power-law interpolation of the RSTN practice, F10.7 scaled by the quiet-Sun spectrum, the radio
// Sun's width, a disc's flux by Rayleigh–Jeans and Perley & Butler's Cas A and Cyg A. Each
// expected value is worked by hand in its comment.
#include "azt/calibration/noise_sources.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

TEST(NoiseSources, NamesRoundTripAndAnUnknownOneIsRefusedByName) {
  for (NoiseSource s :
       {NoiseSource::Sun, NoiseSource::Moon, NoiseSource::CasA, NoiseSource::CygA}) {
    EXPECT_EQ(parse_noise_source(to_string(s)).value(), s);
  }
  const auto bad = parse_noise_source("vega");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("\"vega\""), std::string::npos);
}

TEST(NoiseSources, APowerLawThroughTwoRstnReadings) {
  // 46 SFU at 1415 MHz and 67 at 2695: the exponent at 2304 MHz is
  // ln(2304/1415)/ln(2695/1415) = 0.48752/0.64424 = 0.75674, and 46·(67/46)^0.75674 = 61.14.
  EXPECT_NEAR(power_law_flux(1415.0, 46.0, 2695.0, 67.0, 2304.0), 61.142, 0.001);
  // At either end it returns the reading itself.
  EXPECT_DOUBLE_EQ(power_law_flux(1415.0, 46.0, 2695.0, 67.0, 1415.0), 46.0);
  EXPECT_NEAR(power_law_flux(1415.0, 46.0, 2695.0, 67.0, 2695.0), 67.0, 1e-12);
}

TEST(NoiseSources, F107IsScaledByTheQuietSunSpectrum) {
  // The table at 2800 MHz: 67·(107/67)^(ln(2800/2695)/ln(4995/2695)) = 68.971; at 1296 MHz
  // (between 610 and 1415 MHz) 34·(46/34)^(ln(1296/610)/ln(1415/610)) = 44.571, a ratio of
  // 0.64622; at 10368 MHz 225·(518/225)^(ln(10368/8800)/ln(15400/8800)) = 287.27, 4.1651.
  EXPECT_NEAR(solar_flux_at_band_sfu(100.0, 2800.0), 100.0, 1e-9);
  EXPECT_NEAR(solar_flux_at_band_sfu(100.0, 1296.0), 64.622, 0.001);
  EXPECT_NEAR(solar_flux_at_band_sfu(100.0, 10368.0), 416.51, 0.01);
  // Linear in F10.7.
  EXPECT_NEAR(solar_flux_at_band_sfu(150.0, 2304.0), 1.5 * solar_flux_at_band_sfu(100.0, 2304.0),
              1e-9);
  // Beyond the table the end pair's power law: 144 MHz from 245 and 410 MHz.
  EXPECT_NEAR(solar_flux_at_band_sfu(100.0, 144.0), 9.597, 0.001);
}

TEST(NoiseSources, TheRadioSunIsWiderAtTheLongerWavelengths) {
  EXPECT_DOUBLE_EQ(sun_radio_diameter_deg(432.0), 0.70);
  EXPECT_DOUBLE_EQ(sun_radio_diameter_deg(1296.0), 0.70);
  EXPECT_NEAR(sun_radio_diameter_deg(2304.0), 0.65, 1e-12);
  // 0.65·(0.55/0.65)^(ln(5000/2304)/ln(10368/2304)) = 0.5964.
  EXPECT_NEAR(sun_radio_diameter_deg(5000.0), 0.5964, 0.0001);
  EXPECT_DOUBLE_EQ(sun_radio_diameter_deg(24048.0), 0.55);
  const SourceAtBand sun = sun_at_band(300.0, 10368.0);
  EXPECT_DOUBLE_EQ(sun.flux_jy, 3e6);
  EXPECT_EQ(sun.shape, SourceShape::UniformDisc);
  EXPECT_DOUBLE_EQ(sun.size_deg, 0.55);
}

TEST(NoiseSources, AMoonOfTwoHundredTwentyKelvinByRayleighJeans) {
  // A disc 0.5° across: radius 0.0043633 rad, Ω = π r² = 5.9811e-5 sr. At 10368 MHz,
  // S = 2kTΩf²/c² = 2·1.380649e-23·220·5.9811e-5·(1.0368e10)²/(2.99792458e8)² = 4.3458e-22
  // W m⁻² Hz⁻¹ = 43458 Jy (4.3 SFU).
  EXPECT_NEAR(disc_flux_jy(220.0, 0.5, 10368.0), 43458.0, 1.0);
  // f² and T alike: at a tenth of the frequency and twice the temperature, 2/100 of it.
  EXPECT_NEAR(disc_flux_jy(440.0, 0.5, 1036.8), 0.02 * disc_flux_jy(220.0, 0.5, 10368.0), 1e-6);
  const SourceAtBand moon = moon_at_band(220.0, 0.5, 10368.0);
  EXPECT_NEAR(moon.flux_jy, 43458.0, 1.0);
  EXPECT_DOUBLE_EQ(moon.size_deg, 0.5);
}

TEST(NoiseSources, CasAAndCygAArePerleyAndButler) {
  // Cas A at 1 GHz is 10^3.3584 = 2282 Jy, falling with index −0.75 there; at 1296 MHz
  // (x = log10 1.296 = 0.11261) log S = 3.3584 − 0.7518x − 0.035x² − 0.0710x³ = 3.27320: 1876 Jy,
  // the catalogue's value.
  const auto casa = radio_star_at_band(NoiseSource::CasA, 1000.0);
  ASSERT_TRUE(casa);
  EXPECT_NEAR(casa->flux_jy, 2282.4, 0.1);
  EXPECT_NEAR(radio_star_at_band(NoiseSource::CasA, 1296.0)->flux_jy, 1876.0, 0.5);
  EXPECT_NEAR(radio_star_at_band(NoiseSource::CygA, 1296.0)->flux_jy, 1714.0, 0.5);
  EXPECT_EQ(casa->shape, SourceShape::UniformDisc);
  EXPECT_NEAR(casa->size_deg, 5.0 / 60.0, 1e-12);
  EXPECT_FALSE(radio_star_at_band(NoiseSource::Sun, 1296.0));
  EXPECT_FALSE(radio_star_at_band(NoiseSource::Moon, 1296.0));
}

TEST(NoiseSources, EquivalentGaussianWidths) {
  // A uniform disc's second moment is D²/16 per axis; a Gaussian's is σ² = W²/(8 ln2): equal
  // when W² = ln2·D²/2, W = 0.58871·D.
  EXPECT_NEAR(equivalent_gaussian_width_deg(SourceShape::UniformDisc, 1.0), 0.58871, 1e-5);
  EXPECT_DOUBLE_EQ(equivalent_gaussian_width_deg(SourceShape::Gaussian, 0.53), 0.53);
  EXPECT_DOUBLE_EQ(equivalent_gaussian_width_deg(SourceShape::Point, 0.53), 0.0);
}

}  // namespace
}  // namespace azt::calibration
