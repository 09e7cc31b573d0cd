#pragma once
// The Y-factor a healthy station should see on a source (docs/calibration.md "Sun noise and the
// figure of merit"): the numbers EME operators exchange. A receiver of one polarisation takes half
// of an unpolarised source's flux S, through the dish's effective area η·πD²/4:
//
//   T_A = η·(πD²/4)·S / (2k·K),    Y = (T_sys + T_A)/T_sys,   Y_dB = 10·log10 Y
//
// K ≥ 1 is the source-size correction: a source that is not small against the beam fills it
// only in part. For a Gaussian beam of half-power width W (Baars, "The measurement of large
// antennas with cosmic radio sources", IEEE Trans. AP-21, 1973):
//   a uniform disc of diameter θ:  K = x²/(1 − e^(−x²)),  x² = ln2·(θ/W)²
//     (≈ 1 + 0.35·(θ/W)² for θ < W; the EME tables' 1 + 0.38·(θ/W)² is the same to 1 %);
//   a Gaussian of width θ:         K = 1 + (θ/W)².
// The same relation read backwards is the figure of merit from a measured Y (ITU-R S.733-2, as
// Owen Duffy applies it to Sun noise): G/T = 8πk·(Y − 1)·K / (S·λ²).

#include "azt/calibration/noise_sources.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

struct NoiseStation {
  double freq_mhz = 1296.0;
  double dish_m = 3.0;
  double efficiency = 0.55;    ///< aperture efficiency, (0, 1]
  double tsys_k = 50.0;        ///< system noise temperature on cold sky
  double beamwidth_deg = 0.0;  ///< half-power beamwidth; 0: estimated_beamwidth_deg
};

struct NoiseExpectation {
  double flux_jy = 0.0;        ///< the source at the band, both polarisations
  double beamwidth_deg = 0.0;  ///< the one used (given or estimated)
  double size_factor = 1.0;    ///< K
  double antenna_k = 0.0;      ///< T_A, one polarisation
  double y_db = 0.0;
};

/// A dish's half-power beamwidth, 70·λ/D degrees (1.22 λ/D radians: a dish illuminated with
/// the usual taper; astronomy-and-eme.md §0).
double estimated_beamwidth_deg(double dish_m, double freq_mhz);

/// K for `shape` of `size_deg` in a beam `beamwidth_deg` wide (header).
double size_correction(SourceShape shape, double size_deg, double beamwidth_deg);

/// η·(πD²/4)·S/(2k): a point source's antenna temperature, one polarisation.
double point_antenna_k(double flux_jy, double dish_m, double efficiency);

/// 10·log10((T_sys + T_A)/T_sys).
double y_factor_db(double antenna_k, double tsys_k);

/// The system temperature a measured Y says, given the source's antenna temperature:
/// T_A/(10^(Y/10) − 1). Not finite for Y ≤ 0.
double implied_tsys_k(double y_db, double antenna_k);

/// G/T in dB/K from a measured Y on a source of `flux_jy` whose size correction is `size_factor`
/// (header; ITU-R S.733-2). Not finite for Y ≤ 0.
double g_over_t_db(double y_db, double flux_jy, double freq_mhz, double size_factor);

/// The expected Y of `source` at `station`. Fails, naming the field, on a frequency outside
/// (0, 300000] MHz, a dish outside (0, 500] m, an efficiency outside (0, 1], a T_sys outside
/// (0, 100000] K, a beamwidth outside [0, 30]° or a flux that is negative or not finite.
Result<NoiseExpectation> expected_noise(const NoiseStation& station, const SourceAtBand& source);

}  // namespace azt::calibration
