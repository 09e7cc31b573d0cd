#include "azt/control/hbridge.hpp"

#include <algorithm>
#include <cmath>

namespace azt::control {

HBridgeOutputs HBridge::disable(double now_s) {
  if (direction_ != 0 || !zero_since_s_) zero_since_s_ = now_s;
  direction_ = 0;
  disabled_ = true;
  return HBridgeOutputs{};
}

HBridgeOutputs HBridge::drive(double now_s, double duty) {
  if (!std::isfinite(duty)) return disable(now_s);  // a bad number stops, never drives
  if (disabled_) {
    // After a disable the motor may still turn either way: any side waits the dead time.
    disabled_ = false;
    last_side_ = last_side_ == 0 ? 2 : last_side_;
  }
  duty = std::clamp(duty, -1.0, 1.0);
  const int wanted = duty > 0.0 ? 1 : (duty < 0.0 ? -1 : 0);
  if (wanted == 0) {
    if (direction_ != 0 || !zero_since_s_) zero_since_s_ = now_s;
    direction_ = 0;
    return HBridgeOutputs{0.0, 0.0, true};
  }
  if (wanted != direction_) {
    // Changing sides (or starting): both PWMs must have been zero for the dead time.
    if (direction_ != 0) {
      direction_ = 0;
      zero_since_s_ = now_s;
    }
    // The same side again after a pause may restart at once: nothing reverses.
    const bool reversing = last_side_ != 0 && wanted != last_side_;
    if (reversing && zero_since_s_ && now_s - *zero_since_s_ < dead_time_s_) {
      return HBridgeOutputs{0.0, 0.0, true};
    }
    direction_ = wanted;
    last_side_ = wanted;
  }
  const double magnitude = std::fabs(duty);
  return wanted > 0 ? HBridgeOutputs{magnitude, 0.0, true} : HBridgeOutputs{0.0, magnitude, true};
}

}  // namespace azt::control
