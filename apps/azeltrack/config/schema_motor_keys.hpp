#pragma once
// The schema's keys that [hardware.az|el|pol] and [sim.az|el] share: the controller's brake
// timing and the temperature trip's hysteresis (motor_keys.hpp reads them for both).

#include "config/config_schema.hpp"

namespace azt::app {

constexpr KeySpec motor_number(std::string_view key, std::string_view unit, Range range,
                               std::string_view default_toml, std::string_view help) {
  return {.key = key,
          .type = KeyType::Number,
          .unit = unit,
          .range = range,
          .default_toml = default_toml,
          .help = help};
}

inline constexpr KeySpec kBrakeReleaseKey =
    motor_number("brake_release_s", "s", above_up_to(0.0, 10.0), "1.0",
                 "from the brake line on to the brake off (a T-2X: 0.5 to 1 s)");
inline constexpr KeySpec kBrakeEngageKey =
    motor_number("brake_engage_s", "s", closed(0.0, 10.0), "0.5",
                 "from the brake line off to the brake holding: no new move until then");
inline constexpr KeySpec kBrakeIdleKey =
    motor_number("brake_idle_s", "s", closed(0.0, 600.0), "2.0",
                 "the motor has been still this long before the brake is applied (a stop or "
                 "fault applies it at once)");
inline constexpr KeySpec kTemperatureHysteresisKey =
    motor_number("temperature_hysteresis_c", "°C", closed(0.0, 50.0), "5.0",
                 "a temperature trip may be reset only below the limit less this");

}  // namespace azt::app
