#pragma once
// [mount.az] / [mount.el] / [mount.pol]: what the controller must know about the real antenna's
// axes, whatever drives them. The simulated plant ([sim.az], [sim.el]) is a model of this mount: it
// turns at the mount's rate and reads the mount's encoders; only its imperfections are its own.

#include <cstdint>
#include <optional>

namespace azt::app {

class ConfigFile;

struct AxisMount {
  double max_rate_deg_s = 1.5;     ///< the axis's speed at full drive
  std::uint8_t encoder_bits = 12;  ///< absolute encoder resolution, 9–16 (the EncoderHub's jumpers)
  double time_constant_s = 0.3;    ///< how fast the motor reaches its speed (feed-forward, ramps)
  double min_duty = 0.1;           ///< drive below which the motor does not turn (stiction)
  double backlash_deg = 0.05;      ///< gear play the controller allows for
};

/// [mount.pol]: the polarisation axis (docs/eme.md, "Polarisation axis"), turning a linear feed
/// or the whole array: the axis as [mount.az] describes one, its travel and its window.
struct PolMount {
  AxisMount axis{2.0};     ///< a feed rotator's 2°/s by default
  double min_deg = -95.0;  ///< travel, feed degrees from level (at least 180° wide)
  double max_deg = 95.0;
  double window_deg = 0.5;  ///< a tenth of a dB of polarisation loss at 4° (20·log10 cos)
};

/// [mount.el] fixed_deg: an elevation that does not move (docs/eme.md "Fixed-elevation arrays").
struct FixedElevation {
  double el_deg = 0.0;           ///< 0: an azimuth-only rotator
  double beam_width_deg = 20.0;  ///< the array's vertical half-power beam width
  /// The target is inside the vertical beam: within half the beam width of the fixed angle.
  [[nodiscard]] bool in_beam(double target_el_deg) const;
};

struct MountConfig {
  AxisMount az;
  AxisMount el{1.0};                       ///< the reference elevation axis turns at 1.0°/s
  std::optional<FixedElevation> el_fixed;  ///< only with [mount.el] fixed_deg
  std::optional<PolMount> pol;             ///< only with a [mount.pol] table
};

/// Throws UsageError naming the key on any invalid value.
MountConfig mount_config_from(const ConfigFile& file);

}  // namespace azt::app
