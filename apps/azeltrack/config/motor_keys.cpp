#include "config/motor_keys.hpp"

#include "config/config_file.hpp"
#include "config/hardware_config.hpp"

namespace azt::app {

control::BrakeConfig read_brake_timing(const ConfigSection& s) {
  control::BrakeConfig b;
  b.release_s = s.number("brake_release_s").value_or(b.release_s);
  b.engage_s = s.number("brake_engage_s").value_or(b.engage_s);
  b.idle_s = s.number("brake_idle_s").value_or(b.idle_s);
  auto checked = control::BrakeConfig::make(b);
  if (!checked) fail_field(s, "brake_", checked.error().message);
  return *checked;
}

void read_temperature_hysteresis(const ConfigSection& s, control::MotorTripsConfig& trips) {
  trips.temperature_hysteresis_c =
      s.number("temperature_hysteresis_c").value_or(trips.temperature_hysteresis_c);
}

std::optional<double> read_trip_limit(const ConfigSection& s, const std::string& limit_key,
                                      bool has_reading, const std::string& reading_key,
                                      const std::string& reading_words) {
  if (has_reading) {
    auto limit = s.number(limit_key);
    if (!limit) s.fail(limit_key, "is needed with " + reading_key);
    return limit;
  }
  if (s.has(limit_key)) s.fail(limit_key, "needs " + reading_key + " (" + reading_words + ")");
  return std::nullopt;
}

}  // namespace azt::app
