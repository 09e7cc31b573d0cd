#include "station/guarded_antenna.hpp"

#include <memory>

#include <filesystem>

#include "azt/linux/atomic_file.hpp"
#include "common/usage_error.hpp"

namespace azt::app {

GuardedAntenna::GuardedAntenna(std::unique_ptr<AntennaBackend> inner, const GpioConfig& gpio,
                               GuardParts parts)
    : inner_(std::move(inner)), parts_(std::move(parts)) {
  if (parts_.gpio != nullptr) {
    const auto limit = [this](const std::optional<linux_os::GpioLineSpec>& spec) {
      return spec ? request(*spec, [this](bool) { on_limit_edge(); })
                  : std::unique_ptr<linux_os::GpioInput>();
    };
    az_ccw_ = limit(gpio.az_ccw_limit);
    az_cw_ = limit(gpio.az_cw_limit);
    el_down_ = limit(gpio.el_down_limit);
    el_up_ = limit(gpio.el_up_limit);
    pol_ccw_ = limit(gpio.pol_ccw_limit);
    pol_cw_ = limit(gpio.pol_cw_limit);
    if (gpio.estop) estop_ = request(*gpio.estop, [this](bool on) { on_estop_input(on); });
  }
  std::error_code ec;
  if (std::filesystem::exists(parts_.latch_path, ec)) {
    const auto text = linux_os::read_file(parts_.latch_path);
    latched_ = true;
    latch_reason_ = "E-stop latched before this start (" +
                    (text ? text.value().substr(0, text.value().find('\n')) : "unreadable latch") +
                    "); release the E-stop and clear faults";
    parts_.log(latch_reason_);
    inner_->stop_now(parts_.now_s());
    if (parts_.sequencer != nullptr) parts_.sequencer->set_inhibit(true);
  }
  on_limit_edge();
  if (estop_ && estop_->active()) on_estop_input(true);
}

std::unique_ptr<linux_os::GpioInput> GuardedAntenna::request(const linux_os::GpioLineSpec& spec,
                                                             linux_os::GpioEdgeHandler on_edge) {
  // Pull-ups: a switch to ground that opens, or a wire that breaks, reads as tripped.
  auto line = parts_.gpio->input(spec, linux_os::GpioBias::PullUp, std::move(on_edge));
  if (!line) throw UsageError(line.error().message);
  return std::move(line).value();
}

void GuardedAntenna::on_limit_edge() {
  const auto tripped = [](const std::unique_ptr<linux_os::GpioInput>& in) {
    return in != nullptr && in->active();
  };
  control::LimitSwitches now{tripped(az_ccw_), tripped(az_cw_), tripped(el_down_), tripped(el_up_)};
  const control::LimitPair pol{tripped(pol_ccw_), tripped(pol_cw_)};
  for (const auto& [name, before, after] : {std::tuple{"az CCW", limits_.az_ccw, now.az_ccw},
                                            {"az CW", limits_.az_cw, now.az_cw},
                                            {"el DOWN", limits_.el_down, now.el_down},
                                            {"el UP", limits_.el_up, now.el_up},
                                            {"pol CCW", pol_limits_.reverse, pol.reverse},
                                            {"pol CW", pol_limits_.forward, pol.forward}}) {
    if (before != after) parts_.log(std::string(name) + " limit " + (after ? "tripped" : "clear"));
  }
  limits_ = now;
  pol_limits_ = pol;
  inner_->set_limits(parts_.now_s(), limits_);
  inner_->set_pol_limits(parts_.now_s(), pol_limits_);
}

void GuardedAntenna::on_estop_input(bool active) {
  if (!active) {
    if (latched_) parts_.log("E-stop input released; clear faults to resume");
    return;
  }
  latch("E-stop input active");
}

void GuardedAntenna::latch(const std::string& why) {
  inner_->stop_now(parts_.now_s());
  if (parts_.sequencer != nullptr) parts_.sequencer->set_inhibit(true);
  if (parts_.on_estop) parts_.on_estop();
  if (latched_ && latch_reason_ == why) return;
  latched_ = true;
  latch_reason_ = why;
  parts_.log("E-STOP: " + why + ": drives off, PTT chain released, latched");
  // The drives are already off; only the memory of it for a restart waits for the disk.
  auto error = std::make_shared<std::string>();
  parts_.offload(
      [error, path = parts_.latch_path, text = why + "\n"] {
        if (auto saved = linux_os::write_file_atomically(path, text); !saved) {
          *error = saved.error().message;
        }
      },
      [error, log = parts_.log] {
        if (!error->empty())
          log("E-stop latch not saved (a restart would not remember it): " + *error);
      });
}

std::optional<std::string> GuardedAntenna::hold_reason() const {
  if (latched_) return "the E-stop is latched (" + latch_reason_ + ")";
  if ((parts_.sequencer != nullptr && parts_.sequencer->motion_hold()) ||
      (other_hold_ && other_hold_())) {
    return std::string{"motion is held while the transmitter is keyed"};
  }
  return std::nullopt;
}

std::optional<std::string> GuardedAntenna::home(double now_s, const std::string& axis) {
  if (auto held = hold_reason()) return "no homing now: " + *held;
  return inner_->home(now_s, axis);
}

void GuardedAntenna::tick(double now_s, const control::Demand& demand, const control::AzEl& rate) {
  const auto held = hold_reason();
  const bool hold = held.has_value();
  if (!hold) {
    held_since_s_.reset();
  } else if (!held_since_s_) {
    held_since_s_ = now_s;
  }
  // Homing drives open loop whatever the demand: a hold ends it, before this tick drives and
  // after it (a homing the station's first tick began), and the operator homes once free.
  if (held) inner_->stop_homing(now_s, *held);
  // Held: no position and no jog, so the backend lets any move finish its soft stop (a latched
  // E-stop has already stopped the drives hard).
  inner_->set_pol_demand(latched_ ? control::PolDemand{} : pol_demand_);
  inner_->tick(now_s, hold ? control::Demand{} : demand, hold ? control::AzEl{} : rate);
  if (held) inner_->stop_homing(now_s, *held);
}

void GuardedAntenna::set_pol_demand(const control::PolDemand& demand) { pol_demand_ = demand; }

std::optional<proto::PositionReport> GuardedAntenna::position(double now_s) const {
  auto p = inner_->position(now_s);
  if (p && latched_) p->fault = true;
  return p;
}

void GuardedAntenna::stop_now(double now_s) { inner_->stop_now(now_s); }

std::vector<std::string> GuardedAntenna::faults() const {
  std::vector<std::string> out;
  if (latched_) {
    out.push_back("E-stop: " + latch_reason_ +
                  (estop_ && estop_->active() ? " (input still active)" : ""));
  }
  for (auto& f : inner_->faults()) out.push_back(std::move(f));
  if (parts_.sequencer != nullptr && !parts_.sequencer->fault().empty()) {
    out.push_back(parts_.sequencer->fault());
  }
  return out;
}

void GuardedAntenna::clear_faults() {
  if (latched_ && !(estop_ && estop_->active())) {
    latched_ = false;
    latch_reason_.clear();
    parts_.log("E-stop latch cleared by the operator");
    if (parts_.sequencer != nullptr) parts_.sequencer->set_inhibit(false);
    // After any latch write still queued; a file that cannot go means a restart comes up
    // latched, the safe side, and the operator is told.
    auto error = std::make_shared<std::string>();
    parts_.offload(
        [error, path = parts_.latch_path] {
          std::error_code ec;
          std::filesystem::remove(path, ec);
          if (ec) *error = "cannot remove " + path + ": " + ec.message();
          std::filesystem::remove(path + ".bak", ec);
        },
        [error, log = parts_.log] {
          if (!error->empty()) log("E-stop latch file kept (a restart starts latched): " + *error);
        });
  }
  if (parts_.sequencer != nullptr) parts_.sequencer->clear_fault();
  // The backend's own E-stop fault stays while the latch does.
  if (!latched_) inner_->clear_faults();
}

void GuardedAntenna::set_corrections(const control::PositionCorrections& corrections) {
  inner_->set_corrections(corrections);
}

std::optional<control::AzEl> GuardedAntenna::encoder_reading() const {
  return inner_->encoder_reading();
}

std::string GuardedAntenna::describe() const { return inner_->describe(); }

void GuardedAntenna::set_limits(double now_s, const control::LimitSwitches& limits) {
  limits_ = limits;
  inner_->set_limits(now_s, limits);
}

nlohmann::json GuardedAntenna::state() const {
  nlohmann::json limits = nullptr;
  if (az_ccw_ || az_cw_ || el_down_ || el_up_) {
    limits = {{"az_ccw", limits_.az_ccw},
              {"az_cw", limits_.az_cw},
              {"el_down", limits_.el_down},
              {"el_up", limits_.el_up}};
  }
  if (pol_ccw_ || pol_cw_) {
    if (limits.is_null()) limits = nlohmann::json::object();
    limits["pol_ccw"] = pol_limits_.reverse;
    limits["pol_cw"] = pol_limits_.forward;
  }
  return {{"estop",
           {{"wired", estop_ != nullptr},
            {"input", estop_ != nullptr && estop_->active()},
            {"latched", latched_}}},
          {"limits", limits}};
}

}  // namespace azt::app
