#pragma once
// Which sources a station can scan (docs/calibration.md): each source's antenna temperature from
// its flux density and the dish (noise_expectation.hpp's point_antenna_k; a disc's flux from its
// brightness: noise_sources.hpp's disc_flux_jy), the rise it gives over the system noise (the
// Y-factor EME operators quote as "Sun noise") and its signal-to-noise at one scan point; only
// sources above a threshold are offered.
//
// Formulas (Kraus, Radio Astronomy, 2nd ed., 1986, §3-17 and §6-1; the same in the EME
// literature, e.g. the ARRL Handbook's EME chapter and the W1GHZ Microwave Antenna Book):
//  * a point source of flux density S received in one polarisation (the sources are unpolarised):
//    T_A = η·A·S / (2k), A the dish's geometric area, η its aperture efficiency, k Boltzmann's
//    constant, S in W m⁻² Hz⁻¹ (1 Jy = 1e-26);
//  * a source of Gaussian-equivalent width θ in a Gaussian beam of half-power width W couples
//    W²/(W² + θ²) of that (the convolution's peak; for a disc of brightness T_b this is the
//    familiar T_b·θ²/(θ² + W²));
//  * Y = (T_sys + T_A) / T_sys on the source against cold sky, quoted in dB;
//  * one scan point averages n readings, each scattered by σ dB: its noise in linear units is
//    (10^(σ/10) − 1)/√n of T_sys, and the point's SNR is (Y − 1) over that. An ideal total-power
//    radiometer of bandwidth B integrating τ has σ = 10·log10(1 + 1/√(Bτ)) (Kraus §7-3); real
//    receivers drift and are worse, so the measured scatter is the better figure.

#include <string>
#include <vector>

namespace azt::calibration {

/// What decides how loud a source is at the receiver.
struct DishSetup {
  double dish_m = 10.0;        ///< diameter
  double efficiency = 0.6;     ///< aperture efficiency
  double tsys_k = 50.0;        ///< system noise temperature on cold sky
  double beamwidth_deg = 1.6;  ///< half-power beamwidth (for sources of some size)
};

/// The scatter of one scan point.
struct PointNoise {
  double reading_noise_db = 0.1;  ///< rms of one reading
  double readings = 20.0;         ///< readings averaged per point (dwell × rate)
};

/// A source to consider: its flux density at the band and its size.
struct SourceFlux {
  std::string name;
  double flux_jy = 0.0;
  double size_deg = 0.0;  ///< Gaussian-equivalent width; 0 for a point
};

struct SourceEstimate {
  std::string name;
  double antenna_k = 0.0;  ///< T_A with the beam on it
  double rise_db = 0.0;    ///< Y-factor against cold sky
  double snr_db = 0.0;     ///< the rise against one scan point's noise
  double size_deg = 0.0;
};

/// The fraction of a source of width `size_deg` a beam of `beamwidth_deg` sees: W²/(W² + θ²).
double beam_coupling(double size_deg, double beamwidth_deg);
/// σ of one reading of an ideal radiometer: 10·log10(1 + 1/√(B·τ)).
double radiometer_noise_db(double bandwidth_hz, double integration_s);

/// The rise and SNR of a source whose antenna temperature is `antenna_k`.
SourceEstimate estimate_source(const std::string& name, double antenna_k, double size_deg,
                               const DishSetup& dish, const PointNoise& noise);
/// The same from its flux density.
SourceEstimate estimate_source(const SourceFlux& source, const DishSetup& dish,
                               const PointNoise& noise);

/// The sources worth scanning: SNR at least `min_snr_db`, in the order given.
std::vector<SourceEstimate> worth_scanning(const std::vector<SourceEstimate>& estimates,
                                           double min_snr_db);

}  // namespace azt::calibration
