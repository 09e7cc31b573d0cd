#pragma once
// [mount.az] / [mount.el]: what the controller must know about the real antenna's axes, whatever
// drives them. The simulated plant ([sim.az], [sim.el]) is a model of this mount:
// it turns at the mount's rate and reads the mount's encoders; only its imperfections are its own.

#include <cstdint>

namespace azt::app {

class ConfigFile;

struct AxisMount {
  double max_rate_deg_s = 1.5;     ///< the axis's speed at full drive
  std::uint8_t encoder_bits = 12;  ///< absolute encoder resolution, 9–16 (the EncoderHub's jumpers)
  double time_constant_s = 0.3;    ///< how fast the motor reaches its speed (feed-forward, ramps)
  double min_duty = 0.1;           ///< drive below which the motor does not turn (stiction)
  double backlash_deg = 0.05;      ///< gear play the controller allows for
};

struct MountConfig {
  AxisMount az;
  AxisMount el{1.0};  ///< the reference elevation axis turns at 1.0°/s
};

/// Throws UsageError naming the key on any invalid value.
MountConfig mount_config_from(const ConfigFile& file);

}  // namespace azt::app
