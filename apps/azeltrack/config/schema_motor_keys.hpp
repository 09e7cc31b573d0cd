#pragma once
// The schema's keys that [hardware.az|el|pol] and [sim.az|el] share: the controller's brake
// timing and the temperature trip's hysteresis (motor_keys.hpp reads them for both).

#include "config/schema_keys.hpp"

namespace azt::app {

inline constexpr KeySpec kBrakeReleaseKey =
    number_key("brake_release_s", "s", above_up_to(0.0, 10.0), "1.0",
               "from the brake line on to the brake off (a T-2X: 0.5 to 1 s)");
inline constexpr KeySpec kBrakeEngageKey =
    number_key("brake_engage_s", "s", closed(0.0, 10.0), "0.5",
               "from the brake line off to the brake holding: no new move until then");
inline constexpr KeySpec kBrakeIdleKey =
    number_key("brake_idle_s", "s", closed(0.0, 600.0), "2.0",
               "the motor has been still this long before the brake is applied (a stop or "
               "fault applies it at once)");
inline constexpr KeySpec kTemperatureHysteresisKey =
    number_key("temperature_hysteresis_c", "°C", closed(0.0, 50.0), "5.0",
               "a temperature trip may be reset only below the limit less this");

}  // namespace azt::app
