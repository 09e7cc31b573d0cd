#include "azt/linux/hamlib_rotator_ports.hpp"

#include <array>
#include <chrono>
#include <optional>
#include <string>
#include <utility>

#include "azt/control/axis_geometry.hpp"

namespace azt::linux_os {
namespace {

/// What both axes' ports share: the rotator, the setpoints asked for and the last reading given.
class Box {
 public:
  Box(std::unique_ptr<HamlibRotator> rotator, std::string describe,
      std::optional<double> el_fixed_deg)
      : rotator_(std::move(rotator)), describe_(std::move(describe)), el_fixed_deg_(el_fixed_deg) {}

  /// The box takes both axes in one command: it goes out when either changes, once both are
  /// known. A fixed elevation is always the fixed angle (an azimuth-only box ignores it).
  void set_setpoint(std::size_t axis, std::optional<double> deg) {
    if (!deg || deg == asked_.at(axis)) return;
    asked_.at(axis) = deg;
    const std::optional<double> el = el_fixed_deg_ ? el_fixed_deg_ : asked_[1];
    if (asked_[0] && el) rotator_->command_position(control::wrap_360(*asked_[0]), *el);
  }

  void stop() {
    rotator_->command_stop();
    asked_ = {};  // the next setpoint goes out, even the same one
  }

  /// Axis `axis`'s angle from the box's newest report, once per report; its time on the loop's
  /// clock is `now_s` less the report's age.
  Result<ports::SensorReading> read(std::size_t axis, double now_s) {
    if (!rotator_->connected())
      return fail("hamlib: rotator not connected: " + rotator_->last_error());
    const auto r = rotator_->latest();
    if (!r || (given_.at(axis) && *given_.at(axis) == r->at)) return ports::SensorReading{};
    given_.at(axis) = r->at;
    const double age =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - r->at).count();
    return ports::SensorReading{
        ports::AxisSample{axis == 0 ? control::wrap_360(r->az_deg) : r->el_deg, now_s - age}};
  }

  [[nodiscard]] const std::string& describe() const { return describe_; }

 private:
  std::unique_ptr<HamlibRotator> rotator_;
  std::string describe_;
  std::optional<double> el_fixed_deg_;
  std::array<std::optional<double>, 2> asked_;
  std::array<std::optional<std::chrono::steady_clock::time_point>, 2> given_;
};

class BoxDrive final : public ports::AxisDrive {
 public:
  BoxDrive(std::shared_ptr<Box> box, std::size_t axis) : box_(std::move(box)), axis_(axis) {}
  Result<bool> apply(double /*now_s*/, double /*duty*/, std::optional<double> setpoint) override {
    box_->set_setpoint(axis_, setpoint);
    return true;  // the rotator reports link failures through the sensor
  }
  void off(double /*now_s*/) override { box_->stop(); }
  [[nodiscard]] std::string describe() const override { return box_->describe(); }

 private:
  std::shared_ptr<Box> box_;
  std::size_t axis_;
};

class BoxSensor final : public ports::AxisSensor {
 public:
  BoxSensor(std::shared_ptr<Box> box, std::size_t axis) : box_(std::move(box)), axis_(axis) {}
  Result<ports::SensorReading> read(double now_s) override { return box_->read(axis_, now_s); }
  [[nodiscard]] std::string describe() const override { return box_->describe(); }

 private:
  std::shared_ptr<Box> box_;
  std::size_t axis_;
};

}  // namespace

ports::StationPorts make_hamlib_rotator_ports(std::unique_ptr<HamlibRotator> rotator,
                                              const std::string& describe,
                                              std::optional<double> el_fixed_deg) {
  auto box = std::make_shared<Box>(std::move(rotator), describe, el_fixed_deg);
  ports::StationPorts p;
  for (std::size_t i = 0; i < (el_fixed_deg ? 1U : 2U); ++i) {
    p.drives.at(i) = std::make_unique<BoxDrive>(box, i);
    p.sensors.at(i) = std::make_unique<BoxSensor>(box, i);
  }
  return p;
}

}  // namespace azt::linux_os
