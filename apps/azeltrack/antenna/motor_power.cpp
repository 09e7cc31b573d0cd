#include "antenna/motor_power.hpp"

#include <utility>

namespace azt::app {
namespace {

class SimulatedOutput final : public linux_os::GpioOutput {
 public:
  explicit SimulatedOutput(linux_os::GpioLineSpec spec) : spec_(std::move(spec)) {}
  Result<bool> set(bool active) override {
    active_ = active;
    return true;
  }
  [[nodiscard]] bool active() const override { return active_; }
  [[nodiscard]] const linux_os::GpioLineSpec& spec() const override { return spec_; }

 private:
  linux_os::GpioLineSpec spec_;
  bool active_ = false;
};

}  // namespace

std::unique_ptr<linux_os::GpioOutput> simulated_output(const linux_os::GpioLineSpec& spec) {
  return std::make_unique<SimulatedOutput>(spec);
}

MotorPower::MotorPower(std::unique_ptr<linux_os::GpioOutput> relay, double on_lead_s,
                       std::function<void(const std::string&)> log)
    : relay_(std::move(relay)), on_lead_s_(on_lead_s), log_(std::move(log)) {
  drive(true, -1e9);  // powered from the start, with no lead to wait for
}

void MotorPower::switch_on(double now_s) {
  if (!on_) drive(true, now_s);
}

void MotorPower::switch_off(double now_s) {
  if (on_) drive(false, now_s);
}

void MotorPower::drive(bool on, double now_s) {
  if (auto set = relay_->set(on); !set) {
    // The relay's level is unknown: hold motion (as if off) and say why; the next switch retries.
    log_("motor power: " + linux_os::describe(relay_->spec()) + ": " + set.error().message);
    on_ = false;
    return;
  }
  if (on && !on_) on_since_s_ = now_s;
  if (on != on_) log_(std::string("motor power ") + (on ? "on" : "off"));
  on_ = on;
}

bool MotorPower::motion_hold(double now_s) const {
  return !on_ || now_s - on_since_s_ < on_lead_s_;
}

nlohmann::json MotorPower::to_json(double now_s) const {
  return nlohmann::json{
      {"on", on_}, {"line", linux_os::describe(relay_->spec())}, {"ready", !motion_hold(now_s)}};
}

}  // namespace azt::app
