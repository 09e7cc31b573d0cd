#pragma once
// The sources of a noise measurement (docs/calibration.md "Sun noise and the figure of merit"):
// how bright each is at the band and how big, so the Y-factor a station should see can be worked
// out (noise_expectation.hpp).
//
// - The Sun: the flux at the band, either entered (an RSTN station's reading at a neighbouring
//   frequency, interpolated as a power law: the EME practice of W7PUA's SFU calculator and the
//   moonbounce.dk Sun-noise calculator) or the 10.7 cm index F10.7 scaled by a
//   quiet-Sun spectrum (solar_flux_at_band_sfu). The radio Sun is a disc a little wider than the
//   optical one at the longer wavelengths (astronomy-and-eme.md §8).
// - The Moon: a disc of brightness temperature about 220 K at microwaves (210–250 K with the
//   phase: astronomy-and-eme.md §5; W3IWI on AMSAT-BB, December 2001), its flux by
//   Rayleigh–Jeans.
// - Cassiopeia A and Cygnus A: Perley & Butler 2017 (ApJS 230, 7, table 5) polynomials in
//   log frequency, the ones the catalogue's fluxes come from (astronomy-and-eme.md §5).

#include <optional>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::calibration {

// The physical constants the noise formulas share (noise_sources.cpp, noise_expectation.cpp).
constexpr double kBoltzmann = 1.380649e-23;  ///< J/K (SI 2019, exact)
constexpr double kLightMS = 299792458.0;     ///< m/s (exact)
constexpr double kWattsPerJansky = 1e-26;    ///< W m⁻² Hz⁻¹

enum class NoiseSource { Sun, Moon, CasA, CygA };

/// "sun", "moon", "casa", "cyga".
std::string_view to_string(NoiseSource source);
Result<NoiseSource> parse_noise_source(std::string_view text);

/// How a source's brightness is spread: the size correction depends on it (noise_expectation).
enum class SourceShape {
  Point,
  UniformDisc,  ///< size = its diameter (the Sun, the Moon, a supernova remnant)
  Gaussian,     ///< size = its full width at half maximum
};

/// A source at the band: its flux density (the whole of it, both polarisations) and size.
struct SourceAtBand {
  double flux_jy = 0.0;
  SourceShape shape = SourceShape::Point;
  double size_deg = 0.0;
};

/// The width of the Gaussian with the same second moment as the source, which a beam's
/// width adds to in quadrature (a drift's or a scan's measured width: W² + this²): a uniform
/// disc of diameter D gives √(ln2/2)·D = 0.589·D; a Gaussian its own width; a point 0.
double equivalent_gaussian_width_deg(SourceShape shape, double size_deg);

/// 1 solar flux unit = 10⁻²² W m⁻² Hz⁻¹ = 10⁴ Jy.
inline constexpr double kJanskyPerSfu = 1e4;

/// F10.7 (the 10.7 cm flux, 2800 MHz, SFU) scaled to `freq_mhz` by the quiet-Sun spectrum
/// (docs/calibration.md): the ratio grows from 0.65 at 1296 MHz to 4.2 at 10368 MHz.
double solar_flux_at_band_sfu(double f107_sfu, double freq_mhz);

/// The power law through two measured fluxes (f1, s1) and (f2, s2) evaluated at `freq_mhz`:
/// s1·(s2/s1)^(log(f/f1)/log(f2/f1)). The RSTN stations measure at 245, 410, 610, 1415, 2695,
/// 4995, 8800 and 15400 MHz; take the two either side of the band.
double power_law_flux(double f1_mhz, double s1, double f2_mhz, double s2, double freq_mhz);

/// The radio Sun's diameter at the band: 0.70° at 1296 MHz, 0.65° at 2304, 0.55° at 10368 and
/// above, a power law in frequency between: the widths the EME Sun-noise tables assume
/// (docs/calibration.md).
double sun_radio_diameter_deg(double freq_mhz);

/// The flux density of a uniform disc of brightness temperature `brightness_k` and diameter
/// `diameter_deg` at `freq_mhz` (Rayleigh–Jeans: S = 2k·T·Ω·f²/c²).
double disc_flux_jy(double brightness_k, double diameter_deg, double freq_mhz);

/// The Sun at the band: `flux_sfu` there (entered, or solar_flux_at_band_sfu), a uniform disc of
/// sun_radio_diameter_deg.
SourceAtBand sun_at_band(double flux_sfu, double freq_mhz);
/// The Moon at the band: a uniform disc of `brightness_k` and `diameter_deg` (0.49–0.56° with its
/// distance).
SourceAtBand moon_at_band(double brightness_k, double diameter_deg, double freq_mhz);

/// Cassiopeia A or Cygnus A at `freq_mhz` (Perley & Butler 2017); nullopt for the Sun and Moon.
/// Beyond the fitted range (Cas A 0.2–4 GHz, Cyg A 0.05–12 GHz) the polynomial is extrapolated.
std::optional<SourceAtBand> radio_star_at_band(NoiseSource source, double freq_mhz);

}  // namespace azt::calibration
