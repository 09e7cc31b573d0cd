#pragma once
// The simulated antenna itself ([sim.az], [sim.el], [sim]): two plants behind a simulated
// EncoderHub link, and the faults to inject. What the station's controller knows of the mount is
// not here but in control::StationSetup: a real station runs with that alone.

#include <array>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "azt/calibration/pointing_model.hpp"
#include "azt/control/pot_calibration.hpp"
#include "azt/control/pulse_axis.hpp"
#include "azt/proto/hub_frame.hpp"
#include "azt/sim/actuator_dish_plant.hpp"
#include "azt/sim/axis_plant.hpp"
#include "azt/sim/brake_plant.hpp"
#include "azt/sim/model_hub.hpp"
#include "azt/sim/motor_thermal_plant.hpp"

namespace azt::sim {

/// A plant fault that starts at a given simulated time.
struct ScheduledFault {
  double at_s = 0.0;
  bool azimuth = true;  ///< false: the elevation axis
  AxisFault fault;
};

/// The reed of a simulated actuator, counted from its home switch: the station reads the
/// elevation by its count (`pulses`, its PulseAxis settings) and homes it.
struct SimActuatorReed {
  control::PulseAxisConfig pulses;
  /// The first reed pulse at or after this simulated time is lost (a pulse lost to motor noise):
  /// the next pass of the home switch must reveal it.
  std::optional<double> drop_pulse_at_s;
};

/// A dish whose elevation is a linear actuator (docs/hardware.md, "Linear actuators"): the dish
/// plant moves the elevation, and the station reads it by its own sensor, not through the hub.
/// The sensor is one of two, as on the real dish: the reed counted from a home switch, or a
/// feedback pot on an ADC calibrated in millimetres (a control::PotInputConfig whose `actuator`
/// is the dish's geometry: the same PotInput the daemon runs turns its codes into the angle, and
/// there is nothing to home).
struct SimActuatorElevation {
  ActuatorDishParams dish;
  std::variant<SimActuatorReed, control::PotInputConfig> sensor;

  /// The reed, or nullptr when a pot reads the length.
  [[nodiscard]] const SimActuatorReed* reed() const {
    return std::get_if<SimActuatorReed>(&sensor);
  }
  /// The pot, or nullptr when a reed counts the length.
  [[nodiscard]] const control::PotInputConfig* pot() const {
    return std::get_if<control::PotInputConfig>(&sensor);
  }
};

struct PlantSetup {
  AxisParams az;  ///< the simulated axes: the mount's rate and encoders, their own faults
  AxisParams el;
  /// The plain hub model's frames and link faults (the hub firmware sends CRC-8 frames over a
  /// clean link).
  proto::HubFrameVersion frame_version = proto::HubFrameVersion::Crc8;
  LinkFaults link;
  std::vector<ScheduledFault> faults;  ///< any order: injected in time order
  std::uint64_t seed = 1;              ///< for the link faults
  /// Where the beam really points for the mount's angles ([sim.mount_errors], docs/calibration.md):
  /// the plants turn and the encoders read true, but the beam is off as on a real, imperfect mount.
  calibration::PointingTerms pointing_errors;
  /// The polarisation axis's plant ([sim.pol]), if the station has one. Its absolute encoder is
  /// read directly each tick, not through the hub (the EncoderHub carries two axes).
  std::optional<AxisParams> pol;
  /// A brake on azimuth and elevation (index 0, 1), if any: the shaft does not turn while it
  /// holds, and the station gets a brake line for it.
  std::array<std::optional<BrakePlantParams>, 2> brakes;
  /// The motors' winding temperature (index 0, 1), if modelled: the station reads it as a
  /// temperature sensor on the motor.
  std::array<std::optional<MotorThermalParams>, 2> thermal;
  /// False: the station's elevation does not move ([mount.el] fixed_deg): it gets no elevation
  /// drive or sensor, and the elevation plant stays where it starts.
  bool el_axis = true;
  /// The elevation on a linear actuator (read by a reed's count or a pot), if simulated.
  std::optional<SimActuatorElevation> el_actuator;
};

}  // namespace azt::sim
