#pragma once
// The motors' power relay ([hardware.power], docs/satellites.md "The schedule"): the schedule
// switches the supply off while the station idles for long and on again before a pre-position.
// While it is off, and for `on_lead_s` after it comes on, motion is held (GuardedAntenna's other
// hold): a drive commanded on a dead or still-settling supply would read as a stall.

#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "azt/linux/gpio.hpp"

namespace azt::app {

class MotorPower {
 public:
  /// `relay` is driven on (powered) at once: a station starts able to move.
  MotorPower(std::unique_ptr<linux_os::GpioOutput> relay, double on_lead_s,
             std::function<void(const std::string&)> log);

  void switch_on(double now_s);
  void switch_off(double now_s);
  [[nodiscard]] bool on() const { return on_; }
  /// Off, or on for less than on_lead_s: no motion yet.
  [[nodiscard]] bool motion_hold(double now_s) const;
  /// {"on", "line", "ready"}; `ready` false while motion is held.
  [[nodiscard]] nlohmann::json to_json(double now_s) const;

 private:
  void drive(bool on, double now_s);

  std::unique_ptr<linux_os::GpioOutput> relay_;
  double on_lead_s_;
  std::function<void(const std::string&)> log_;
  bool on_ = true;
  double on_since_s_ = -1e9;
};

/// The `sim` backend's relay line ("sim:N"): remembers its level, fails never.
std::unique_ptr<linux_os::GpioOutput> simulated_output(const linux_os::GpioLineSpec& spec);

}  // namespace azt::app
