#include "azt/hands/pad_state.hpp"

namespace azt::hands {

void apply_pad_event(PadState& state, unsigned type, unsigned code, int value) {
  if (type == kEvKey) {
    if (value == 0) {
      state.pressed.erase(code);
    } else {
      state.pressed.insert(code);
    }
  } else if (type == kEvAbs) {
    state.values[code] = value;
  }
}

namespace {

double deflection(const PadState& state, unsigned code, double dead_zone) {
  const auto range = state.ranges.find(code);
  const auto value = state.values.find(code);
  if (range == state.ranges.end() || value == state.values.end()) return 0.0;
  return pad_deflection(value->second, range->second, dead_zone);
}

int value_of(const PadState& state, unsigned code) {
  const auto it = state.values.find(code);
  return it == state.values.end() ? 0 : it->second;
}

}  // namespace

HandInputs pad_inputs(const PadLayout& layout, const PadState& state) {
  HandInputs in;
  in.az_deflection = deflection(state, layout.az_axis, layout.dead_zone);
  const double el = deflection(state, layout.el_axis, layout.dead_zone);
  in.el_deflection = layout.el_inverted ? -el : el;
  if (layout.use_dpad) {
    in.cw = value_of(state, kAbsHat0X) > 0;
    in.ccw = value_of(state, kAbsHat0X) < 0;
    in.up = value_of(state, kAbsHat0Y) < 0;
    in.down = value_of(state, kAbsHat0Y) > 0;
  }
  in.stop = state.pressed.count(layout.stop_button) != 0;
  in.park = state.pressed.count(layout.park_button) != 0;
  return in;
}

}  // namespace azt::hands
