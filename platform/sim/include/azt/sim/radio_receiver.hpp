#pragma once
// The simulated receiver of pointing calibration (docs/calibration.md): the power a total-power
// radiometer reads through a Gaussian beam of configured width, from the Sun, the Moon and the
// radio sources, each a Gaussian of its own angular size, over the system's noise; every reading
// carries Gaussian noise of a configured size in dB (seeded: a run repeats exactly).
// Antenna temperatures: a disc of brightness T_b and size θ fills a beam of width W by
// θ²/(θ² + W²) (astronomy-and-eme.md §5, K_fill); a point source of flux S gives η·S·A/(2k).

#include <cstdint>
#include <random>
#include <vector>

#include "azt/control/modes.hpp"

namespace azt::sim {

/// A source on the sky at one instant.
struct RadioEmitter {
  control::AzEl sky;
  double peak_k = 0.0;    ///< antenna temperature with the beam on it
  double size_deg = 0.0;  ///< its Gaussian-equivalent width (0: a point)
};

struct ReceiverSetup {
  double beamwidth_deg = 1.6;  ///< half-power beamwidth
  double tsys_k = 50.0;        ///< system noise temperature on cold sky
  double noise_db = 0.1;       ///< rms of one reading
  double rate_hz = 5.0;        ///< readings per second
  double dish_m = 10.0;        ///< for the radio sources' antenna temperatures
  double efficiency = 0.6;     ///< aperture efficiency
  std::uint64_t seed = 1;
};

class SimulatedReceiver {
 public:
  explicit SimulatedReceiver(const ReceiverSetup& setup);

  /// One reading with the beam at `beam`: dB over the system noise on cold sky, with noise.
  double read_db(const control::AzEl& beam, const std::vector<RadioEmitter>& sky);
  /// The same without noise.
  [[nodiscard]] double expected_db(const control::AzEl& beam,
                                   const std::vector<RadioEmitter>& sky) const;
  /// The rise a source gives with the beam on it, dB.
  [[nodiscard]] double peak_rise_db(const RadioEmitter& source) const;

  /// Antenna temperature of a disc of brightness `brightness_k` and width `size_deg`.
  [[nodiscard]] double disc_k(double brightness_k, double size_deg) const;
  /// Antenna temperature of a point source of `flux_jy` (one polarisation).
  [[nodiscard]] double point_k(double flux_jy) const;

  [[nodiscard]] const ReceiverSetup& setup() const { return setup_; }

 private:
  ReceiverSetup setup_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_;
};

}  // namespace azt::sim
