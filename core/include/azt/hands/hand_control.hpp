#pragma once
// The hands at the mast: jog buttons (CW, CCW, UP, DOWN), STOP and PARK, and a game pad's stick,
// turned into what the station's front door is asked, one control tick at a time (docs/hardware.md,
// "Buttons and a game pad"). Pure: the daemon feeds it the debounced buttons and the stick's
// deflections; the same rules as every other source then apply at the door.
//
// A held direction (or a deflected stick) asks for a continuous move every tick: the front door's
// continuous move stops by itself when not renewed within a second (modes.hpp), so a wire that
// breaks while a button is held, or a daemon that stops reading the pad, stops the motor. Letting
// go asks once for a release (hold where it stands). STOP and PARK act on the press, once: a
// button held down does not repeat them, and while STOP is held nothing moves.

#include <cstdint>
#include <string_view>

namespace azt::hands {

/// What the hands hold at this tick.
struct HandInputs {
  bool cw = false;
  bool ccw = false;
  bool up = false;
  bool down = false;
  bool stop = false;
  bool park = false;
  double az_deflection = 0.0;  ///< the stick, −1…+1 (+1 clockwise), 0 without a pad
  double el_deflection = 0.0;  ///< +1 up
};

enum class HandActionKind : std::uint8_t { None, Move, Release, Stop, Park };
std::string_view to_string(HandActionKind kind);

/// What to ask the front door now. Move: signed speeds, a fraction of each axis's full rate
/// (0: that axis holds).
struct HandAction {
  HandActionKind kind = HandActionKind::None;
  double az_speed = 0.0;
  double el_speed = 0.0;
};

struct HandControlConfig {
  double button_speed = 1.0;  ///< a jog button's speed, a fraction of the axis's full rate
};

class HandControl {
 public:
  explicit HandControl(HandControlConfig config) : config_(config) {}

  /// One tick: what the hands ask now.
  HandAction update(const HandInputs& in);

 private:
  [[nodiscard]] double speed(bool forward, bool back, double deflection) const;

  HandControlConfig config_;
  bool stop_held_ = false;
  bool park_held_ = false;
  bool moving_ = false;
};

}  // namespace azt::hands
