#include "azt/hands/hand_control.hpp"

#include <algorithm>

namespace azt::hands {

std::string_view to_string(HandActionKind kind) {
  switch (kind) {
    case HandActionKind::None:
      return "none";
    case HandActionKind::Move:
      return "move";
    case HandActionKind::Release:
      return "release";
    case HandActionKind::Stop:
      return "stop";
    case HandActionKind::Park:
      return "park";
  }
  return "none";
}

double HandControl::speed(bool forward, bool back, double deflection) const {
  // Both buttons of one axis at once cancel: a stuck or crossed pair never picks a side.
  if (forward || back) return forward == back ? 0.0 : (forward ? 1.0 : -1.0) * config_.button_speed;
  return std::clamp(deflection, -1.0, 1.0);
}

HandAction HandControl::update(const HandInputs& in) {
  const bool stop_pressed = in.stop && !stop_held_;
  const bool park_pressed = in.park && !park_held_;
  stop_held_ = in.stop;
  park_held_ = in.park;
  if (in.stop) {
    moving_ = false;
    return {stop_pressed ? HandActionKind::Stop : HandActionKind::None, 0.0, 0.0};
  }
  if (park_pressed) {
    moving_ = false;
    return {HandActionKind::Park, 0.0, 0.0};
  }
  const double az = speed(in.cw, in.ccw, in.az_deflection);
  const double el = speed(in.up, in.down, in.el_deflection);
  if (az != 0.0 || el != 0.0) {
    moving_ = true;
    return {HandActionKind::Move, az, el};
  }
  if (!moving_) return {};
  moving_ = false;
  return {HandActionKind::Release, 0.0, 0.0};
}

}  // namespace azt::hands
