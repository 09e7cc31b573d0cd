#pragma once
// [gamepad]: a USB game pad or joystick at the mast (docs/hardware.md, "Buttons and a game pad"),
// read through Linux input events (hands/hand_pad.hpp). Absent: no pad is looked for.

#include <optional>
#include <string>

namespace azt::app {

class ConfigFile;

struct GamepadConfig {
  /// The pad's input node; best its stable /dev/input/by-id/…-event-joystick link, which names
  /// the same pad whichever USB socket it is in.
  std::string device;
  /// The stick's dead zone, a fraction of its half range beyond the driver's own flat zone.
  double dead_zone = 0.15;
  /// The speed at full deflection and of the D-pad, a fraction of the axis's full rate.
  double speed = 1.0;
  int park_slot = 1;  ///< the [[park]] slot START parks in
};

/// nullopt without a [gamepad] device; throws UsageError naming the key on an invalid value.
std::optional<GamepadConfig> read_gamepad(const ConfigFile& file);

}  // namespace azt::app
