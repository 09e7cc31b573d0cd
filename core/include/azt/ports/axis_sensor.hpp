#pragma once
// What reads one axis, as the station controller sees it: an EncoderHub's frames,
// a potentiometer on an ADC, a rotator box's own position report, or the simulated encoder.
// Implemented by the simulation and the Linux and Hamlib adapters.

#include <optional>
#include <string>

#include "azt/util/result.hpp"

namespace azt::ports {

/// One reading: the angle in degrees as the sensor reports it (before the station's
/// corrections), and when it was taken on the control loop's clock (a hub frame that arrived
/// between ticks carries its own arrival time, so staleness counts from the frame).
struct AxisSample {
  double deg = 0.0;
  double at_s = 0.0;
};

/// A new sample, or nullopt when there is nothing new yet (an ADC conversion still running, a
/// hub between frames): no fault, the last reading ages and goes stale if nothing follows.
using SensorReading = std::optional<AxisSample>;

class AxisSensor {
 public:
  AxisSensor() = default;
  AxisSensor(const AxisSensor&) = delete;
  AxisSensor& operator=(const AxisSensor&) = delete;
  AxisSensor(AxisSensor&&) = delete;
  AxisSensor& operator=(AxisSensor&&) = delete;
  virtual ~AxisSensor() = default;

  /// Called once a control tick at `now_s`; never waits for a device. An error for a bus
  /// failure, a lost link, a conversion that never finishes or a broken wire: never a plausible
  /// angle made of a bad sample.
  virtual Result<SensorReading> read(double now_s) = 0;
  /// A fault this sensor holds until the operator clears it (a hub whose frames are not at the
  /// mount's resolution): while set, the motors stay off. Most sensors never latch.
  [[nodiscard]] virtual std::optional<std::string> latched_fault() const { return std::nullopt; }
  virtual void clear_fault() {}
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace azt::ports
