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
  external_locked_ = false;
  jog_.reset();
  mode_ = Mode::Track;
  who_ = std::move(target_name);
}

Result<Mode> ModeController::manual(AzEl position) {
  auto p = checked(position);
  if (!p) return p.error();
  external_locked_ = false;
  jog_.reset();
  mode_ = Mode::Manual;
  fixed_ = *p;
  who_ = "manual";
  return mode_;
}

Result<Mode> ModeController::park(int slot) {
  if (slot < 1 || slot > kParkSlots) return fail("park slot must be 1 to 4");
  external_locked_ = false;
  jog_.reset();
  mode_ = Mode::Park;
  park_slot_ = slot;
  fixed_ = slots_[static_cast<std::size_t>(slot - 1)].position;
  who_ = slots_[static_cast<std::size_t>(slot - 1)].name;
  return mode_;
}

Result<Mode> ModeController::external(AzEl position, std::string client) {
  if (external_locked_) return fail("refused: STOP was pressed on the console");
  auto p = checked(position);
  if (!p) return p.error();
  jog_.reset();
  external_waiting_ = false;
  mode_ = Mode::External;
  fixed_ = *p;
  who_ = std::move(client);
  return mode_;
}

Result<Jog> ModeController::checked(Jog jog) {
  if (jog.az < -1 || jog.az > 1 || jog.el < -1 || jog.el > 1 || (jog.az == 0 && jog.el == 0)) {
    return fail("a move needs a direction on at least one axis");
  }
  // NaN fails both comparisons, so it is refused with the rest.
  const auto speed_ok = [](int direction, double speed) {
    return direction == 0 || (speed > 0.0 && speed <= 1.0);
  };
  if (!speed_ok(jog.az, jog.az_speed) || !speed_ok(jog.el, jog.el_speed)) {
    return fail("a move's speed must be above 0 and at most 1 (the axis's full rate)");
  }
  return jog;
}

void ModeController::start_jog(Mode mode, Jog jog, std::string client, double now_s) {
  mode_ = mode;
  external_waiting_ = false;
  jog_ = jog;
  jog_heard_s_ = now_s;
  who_ = std::move(client);
}

Result<Mode> ModeController::external_jog(Jog jog, std::string client, double now_s) {
  if (external_locked_) return fail("refused: STOP was pressed on the console");
  auto j = checked(jog);
  if (!j) return j.error();
  start_jog(Mode::External, *j, std::move(client), now_s);
  return mode_;
}

Result<Mode> ModeController::manual_jog(Jog jog, std::string client, double now_s) {
  auto j = checked(jog);
  if (!j) return j.error();
  start_jog(Mode::Manual, *j, std::move(client), now_s);
  return mode_;
}

void ModeController::end_jog(std::string_view client) {
  if (!jog_ || client != who_) return;
  jog_.reset();
  mode_ = Mode::Stop;
  who_ = "released by " + std::string(client);
}

void ModeController::heard_from(std::string_view client, double now_s) {
  if (jog_ && client == who_) jog_heard_s_ = now_s;
}

void ModeController::update(double now_s) {
  if (jog_ && now_s - jog_heard_s_ > kJogKeepAliveS) {
    jog_.reset();
    mode_ = Mode::Stop;
    who_ = "move stopped: " + who_ + " silent for 1 s";
  }
}

void ModeController::stop(bool from_console) {
  jog_.reset();
  mode_ = Mode::Stop;
  who_ = from_console ? "console" : "stop";
  external_locked_ = from_console;
}

void ModeController::local_stop(std::string_view who) {
  stop(true);
  who_ = std::string(who);
}

void ModeController::allow_external() {
  jog_.reset();
  external_locked_ = false;
  external_waiting_ = true;
  mode_ = Mode::External;
  who_ = "PC programs";
}

std::optional<AzEl> ModeController::fixed_target() const {
  const bool external_fixed = mode_ == Mode::External && !jog_ && !external_waiting_;
  if (mode_ == Mode::Manual || mode_ == Mode::Park || external_fixed) {
    return fixed_;
  }
  return std::nullopt;
}

namespace {
Demand hold_or_go(std::optional<AzEl> position, std::string reason) {
  return Demand{position, std::move(reason), std::nullopt};
}
}  // namespace

Demand ModeController::demand(const std::optional<AzEl>& sky) const {
  switch (mode_) {
    case Mode::Stop:
      return Demand{std::nullopt, "stopped: " + who_, std::nullopt};
    case Mode::Manual:
    case Mode::Park:
    case Mode::External:
      if (jog_)
        return Demand{std::nullopt, std::string(to_string(mode_)) + " move by " + who_, jog_};
      if (mode_ == Mode::External && external_waiting_) {
        return hold_or_go(std::nullopt, "EXT: waiting for a PC program's position");
      }
      return hold_or_go(fixed_, std::string(to_string(mode_)) + " " + who_);
    case Mode::Track:
      break;
  }
  if (!sky) return hold_or_go(std::nullopt, "holding: no position for " + who_);
  if (sky->el_deg < min_el_deg_) {
    if (policy_ == OutOfRangePolicy::Park) {
      return hold_or_go(slots_[0].position,
                        who_ + " below the horizon limit: parked at " + slots_[0].name);
    }
    return hold_or_go(std::nullopt, "holding: " + who_ + " below the horizon limit");
  }
  return hold_or_go(*sky, "tracking " + who_);
}

void ModeController::set_park_slots(const std::array<ParkSlot, kParkSlots>& slots) {
  slots_ = slots;
  if (mode_ == Mode::Park && park_slot_ >= 1 && park_slot_ <= kParkSlots) {
    fixed_ = slots_[static_cast<std::size_t>(park_slot_ - 1)].position;
    who_ = slots_[static_cast<std::size_t>(park_slot_ - 1)].name;
  }
}

}  // namespace azt::control
