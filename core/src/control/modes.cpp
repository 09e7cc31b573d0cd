#include "azt/control/modes.hpp"

#include <cmath>
#include <utility>

namespace azt::control {

std::string_view to_string(Mode mode) {
  switch (mode) {
    case Mode::Track:
      return "TRACK";
    case Mode::Manual:
      return "MAN";
    case Mode::Park:
      return "PARK";
    case Mode::External:
      return "EXT";
    case Mode::Stop:
      return "STOP";
  }
  return "STOP";
}

Result<AzEl> ModeController::checked(AzEl position) {
  if (!std::isfinite(position.az_deg) || !std::isfinite(position.el_deg) || position.az_deg < 0.0 ||
      position.az_deg >= 360.0 || position.el_deg < -10.0 || position.el_deg > 180.0) {
    return fail("position must be az 0..360, el -10..180 degrees");
  }
  return position;
}

void ModeController::track(std::string target_name) {
  mode_ = Mode::Track;
  who_ = std::move(target_name);
}

Result<Mode> ModeController::manual(AzEl position) {
  auto p = checked(position);
  if (!p) return p.error();
  mode_ = Mode::Manual;
  fixed_ = *p;
  who_ = "manual";
  return mode_;
}

Result<Mode> ModeController::park(int slot) {
  if (slot < 1 || slot > kParkSlots) return fail("park slot must be 1 to 4");
  mode_ = Mode::Park;
  park_slot_ = slot;
  fixed_ = slots_[static_cast<std::size_t>(slot - 1)].position;
  who_ = slots_[static_cast<std::size_t>(slot - 1)].name;
  return mode_;
}

Result<Mode> ModeController::external(AzEl position, std::string client) {
  auto p = checked(position);
  if (!p) return p.error();
  mode_ = Mode::External;
  fixed_ = *p;
  who_ = std::move(client);
  return mode_;
}

void ModeController::stop() {
  mode_ = Mode::Stop;
  who_ = "stop";
}

Demand ModeController::demand(const std::optional<AzEl>& sky) const {
  switch (mode_) {
    case Mode::Stop:
      return Demand{std::nullopt, "stopped"};
    case Mode::Manual:
    case Mode::Park:
    case Mode::External:
      return Demand{fixed_, std::string(to_string(mode_)) + " " + who_};
    case Mode::Track:
      break;
  }
  if (!sky) return Demand{std::nullopt, "holding: no position for " + who_};
  if (sky->el_deg < min_el_deg_) {
    if (policy_ == OutOfRangePolicy::Park) {
      return Demand{slots_[0].position,
                    who_ + " below the horizon limit: parked at " + slots_[0].name};
    }
    return Demand{std::nullopt, "holding: " + who_ + " below the horizon limit"};
  }
  return Demand{*sky, "tracking " + who_};
}

}  // namespace azt::control
