#pragma once
// What an axis's motor has besides its drive (docs/hardware.md, "Brake, current and
// temperature"): the brake's release line, and the readings that protect the motor (the
// driver's current sense, a temperature sensor, the driver's fault line). Both are optional per
// axis; the Linux adapters and the simulation implement them.

#include <optional>
#include <string>

#include "azt/util/result.hpp"

namespace azt::ports {

/// The brake's line: energised releases the brake; a spring applies it when the line goes off.
class BrakeLine {
 public:
  BrakeLine() = default;
  BrakeLine(const BrakeLine&) = delete;
  BrakeLine& operator=(const BrakeLine&) = delete;
  BrakeLine(BrakeLine&&) = delete;
  BrakeLine& operator=(BrakeLine&&) = delete;
  virtual ~BrakeLine() = default;

  /// The line as the axis's brake wants it until the next tick. A write error is returned; the
  /// station then stops.
  virtual Result<bool> apply(double now_s, bool release) = 0;
  /// Off (the brake applied) now, best effort: never fails, never waits.
  virtual void off(double now_s) = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
};

/// One tick's motor readings; an empty field is nothing new (or no such input).
struct MotorSample {
  std::optional<double> current_a;
  std::optional<double> temperature_c;
  std::optional<bool> driver_fault;  ///< true: the driver reports a fault
};

class MotorSensor {
 public:
  MotorSensor() = default;
  MotorSensor(const MotorSensor&) = delete;
  MotorSensor& operator=(const MotorSensor&) = delete;
  MotorSensor(MotorSensor&&) = delete;
  MotorSensor& operator=(MotorSensor&&) = delete;
  virtual ~MotorSensor() = default;

  /// Called once a control tick; never waits for a device (no more than an axis sensor does).
  /// An error when an input cannot be read: the axis then trips on a reading that is not a
  /// number.
  virtual Result<MotorSample> read(double now_s) = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace azt::ports
