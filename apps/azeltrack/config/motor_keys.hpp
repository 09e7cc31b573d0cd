#pragma once
// The keys of an axis's brake timing and motor trips that a real axis ([hardware.az|el|pol])
// and a simulated one ([sim.az|el]) share, read once for both (docs/hardware.md "Brake, current
// and temperature", docs/control.md "The simulated antenna").

#include <optional>
#include <string>

#include "azt/control/brake.hpp"
#include "azt/control/motor_trips.hpp"

namespace azt::app {

class ConfigSection;

/// brake_release_s, brake_engage_s and brake_idle_s: the controller's brake timing, checked by
/// control::BrakeConfig::make. Throws UsageError naming the key.
control::BrakeConfig read_brake_timing(const ConfigSection& s);

/// temperature_hysteresis_c into `trips` (its axis, limits and current timing are the caller's).
void read_temperature_hysteresis(const ConfigSection& s, control::MotorTripsConfig& trips);

/// A trip's limit (`limit_key`: current_limit_a, temperature_limit_c), given exactly when the
/// reading it watches is (`has_reading`, given by `reading_key`; `reading_words` say what that
/// is): a reading without a limit would watch nothing, and a limit without a reading the same.
/// Throws UsageError naming the key.
std::optional<double> read_trip_limit(const ConfigSection& s, const std::string& limit_key,
                                      bool has_reading, const std::string& reading_key,
                                      const std::string& reading_words);

}  // namespace azt::app
