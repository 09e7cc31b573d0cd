#pragma once
// The simulated antenna's mechanics: two plants (motor, gear, backlash, encoder), stepped with
// the drives' duties. What reads their encoders is a SimulatedHub (simulated_hub.hpp): the plain
// model or the hub firmware on a simulated AVR.

#include "azt/sim/axis_plant.hpp"

namespace azt::sim {

class SimAntenna {
 public:
  SimAntenna(const AxisParams& az, const AxisParams& el) : az_(az), el_(el) {}

  /// Advances both plants by `dt_s` with the given duties.
  void step(double az_duty, double el_duty, double dt_s) {
    az_.step(az_duty, dt_s);
    el_.step(el_duty, dt_s);
  }
  void inject(bool azimuth, const AxisFault& fault) { (azimuth ? az_ : el_).inject(fault); }
  /// The elevation moved by a linear actuator's model instead of its motor (AxisPlant::follow).
  void el_follows(double shaft_deg, double rate_deg_s) { el_.follow(shaft_deg, rate_deg_s); }

  [[nodiscard]] const AxisPlant& az() const { return az_; }
  [[nodiscard]] const AxisPlant& el() const { return el_; }

 private:
  AxisPlant az_;
  AxisPlant el_;
};

}  // namespace azt::sim
