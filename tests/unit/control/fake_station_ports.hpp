#pragma once
// Fake station ports for PortedStation's tests: what the sensor reads next and what the drive
// was told, shared by the test and the port objects.

#include <memory>
#include <optional>
#include <string>

#include "azt/ports/axis_drive.hpp"
#include "azt/ports/axis_sensor.hpp"

namespace azt::control {

/// What a fake port pair shows the test: the sensor's next reading and what the drive was told.
struct FakeAxis {
  std::optional<double> reading_deg = 0.0;  ///< nullopt: the sensor has nothing new
  std::optional<std::string> read_error;
  std::optional<std::string> write_error;
  double duty = 0.0;
  int offs = 0;
};

class FakeDrive final : public ports::AxisDrive {
 public:
  explicit FakeDrive(std::shared_ptr<FakeAxis> axis) : axis_(std::move(axis)) {}
  Result<bool> apply(double /*now_s*/, double duty, std::optional<double> /*setpoint*/) override {
    if (axis_->write_error) return fail(*axis_->write_error);
    axis_->duty = duty;
    return true;
  }
  void off(double /*now_s*/) override {
    axis_->duty = 0.0;
    ++axis_->offs;
  }
  [[nodiscard]] std::string describe() const override { return "fake drive"; }

 private:
  std::shared_ptr<FakeAxis> axis_;
};

class FakeSensor final : public ports::AxisSensor {
 public:
  explicit FakeSensor(std::shared_ptr<FakeAxis> axis) : axis_(std::move(axis)) {}
  Result<ports::SensorReading> read(double now_s) override {
    if (axis_->read_error) return fail(*axis_->read_error);
    if (!axis_->reading_deg) return ports::SensorReading{};
    return ports::SensorReading{ports::AxisSample{*axis_->reading_deg, now_s}};
  }
  [[nodiscard]] std::string describe() const override { return "fake sensor"; }

 private:
  std::shared_ptr<FakeAxis> axis_;
};

}  // namespace azt::control
