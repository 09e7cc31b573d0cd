#include "hands/hand_door.hpp"

#include <algorithm>
#include <cmath>

namespace azt::app {
namespace {

int direction_of(double speed) { return speed > 0.0 ? 1 : speed < 0.0 ? -1 : 0; }

double rounded_speed(double speed) {
  return std::clamp(std::round(std::fabs(speed) * 20.0) / 20.0, 0.05, 1.0);
}

bool same(const control::Jog& a, const control::Jog& b) {
  return a.az == b.az && a.el == b.el && a.az_speed == b.az_speed && a.el_speed == b.el_speed;
}

}  // namespace

control::Jog jog_of(const hands::HandAction& action) {
  return control::Jog{direction_of(action.az_speed), direction_of(action.el_speed),
                      rounded_speed(action.az_speed), rounded_speed(action.el_speed)};
}

void HandDoor::forget() {
  moving_.reset();
  refused_ = false;
}

void HandDoor::move(const control::Jog& jog) {
  if (refused_) return;
  if (moving_ && same(*moving_, jog)) {
    commands_.heard_from(source_);
    return;
  }
  if (commands_.jog(source_, jog).accepted()) {
    moving_ = jog;
  } else {
    moving_.reset();
    refused_ = true;
  }
}

void HandDoor::apply(const hands::HandAction& action) {
  switch (action.kind) {
    case hands::HandActionKind::None:
      return;
    case hands::HandActionKind::Move:
      move(jog_of(action));
      return;
    case hands::HandActionKind::Release:
      if (moving_) commands_.release(source_);
      forget();
      return;
    case hands::HandActionKind::Stop:
      forget();
      commands_.stop(source_);
      return;
    case hands::HandActionKind::Park:
      forget();
      (void)commands_.point(source_, ParkTarget{park_slot_});
      return;
  }
}

}  // namespace azt::app
