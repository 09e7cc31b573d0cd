#pragma once
// A game pad's or joystick's present state as its Linux input events leave it, and which of its
// controls steer which way (docs/hardware.md, "Buttons and a game pad"). Pure: the numbers are the
// kernel's event types and codes (linux/input-event-codes.h, quoted below), so recorded event
// streams are replayed here without a device; platform/linux's EvdevPad feeds it from libevdev.

#include <map>
#include <set>

#include "azt/hands/hand_control.hpp"
#include "azt/hands/pad_axis.hpp"

namespace azt::hands {

// linux/input-event-codes.h
inline constexpr unsigned kEvKey = 0x01;
inline constexpr unsigned kEvAbs = 0x03;
inline constexpr unsigned kAbsX = 0x00;
inline constexpr unsigned kAbsY = 0x01;
inline constexpr unsigned kAbsHat0X = 0x10;   ///< the D-pad: −1, 0, +1
inline constexpr unsigned kAbsHat0Y = 0x11;   ///< −1 is up
inline constexpr unsigned kBtnSouth = 0x130;  ///< A on an Xbox pad, ✕ on a PlayStation one
inline constexpr unsigned kBtnEast = 0x131;
inline constexpr unsigned kBtnStart = 0x13b;

struct PadState {
  std::map<unsigned, PadAxisRange> ranges;  ///< each absolute axis the pad has
  std::map<unsigned, int> values;           ///< its present value
  std::set<unsigned> pressed;               ///< the keys and buttons held now
};

/// One event (type, code, value) applied to `state`: a key's press (value 1, and 2 for the
/// kernel's autorepeat) or release (0), an absolute axis's new value. Other types (the SYN
/// reports between event groups, relative axes, force feedback) change nothing.
void apply_pad_event(PadState& state, unsigned type, unsigned code, int value);

/// Which controls steer (defaults: the left stick, the D-pad as four jog buttons, A for STOP,
/// START for PARK).
struct PadLayout {
  unsigned az_axis = kAbsX;
  unsigned el_axis = kAbsY;
  bool el_inverted = true;  ///< sticks report Y growing downwards: pushed up is negative
  bool use_dpad = true;
  unsigned stop_button = kBtnSouth;
  unsigned park_button = kBtnStart;
  double dead_zone = 0.15;  ///< of the half range, beyond the driver's flat zone
};

/// What the pad's hands hold now, for HandControl.
HandInputs pad_inputs(const PadLayout& layout, const PadState& state);

}  // namespace azt::hands
