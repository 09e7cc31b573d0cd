#include "azt/control/motor_trips.hpp"

#include <algorithm>
#include <cmath>

#include "azt/util/format_number.hpp"

namespace azt::control {
namespace {

bool in_range(double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; }

// Seconds to two decimals at most, as an operator reads them ("0.5", "0.25").
std::string seconds_text(double s) { return format_number(std::round(s * 100.0) / 100.0); }

std::string celsius(double c) { return format_fixed(c, 1) + " °C"; }

}  // namespace

Result<CurrentSense> CurrentSense::make(const CurrentSense& c) {
  if (!in_range(c.amps_per_volt, 0.0, 1000.0) || c.amps_per_volt == 0.0) {
    return fail("amps_per_volt must be above 0 and at most 1000");
  }
  if (!in_range(c.offset_v, 0.0, 5.0)) return fail("offset_v must be 0 to 5 V");
  return c;
}

double CurrentSense::amps(double sense_v) const {
  if (std::isnan(sense_v)) return sense_v;
  return std::max(0.0, (sense_v - offset_v) * amps_per_volt);
}

std::string_view to_string(MotorTrip trip) {
  switch (trip) {
    case MotorTrip::None:
      return "none";
    case MotorTrip::Current:
      return "motor current";
    case MotorTrip::Temperature:
      return "motor temperature";
    case MotorTrip::DriverFault:
      return "motor driver fault";
    case MotorTrip::BadReading:
      return "motor reading not a number";
  }
  return "unknown";
}

Result<MotorTripsConfig> MotorTripsConfig::make(const MotorTripsConfig& c) {
  if (c.axis.empty()) return fail("axis must be named");
  if (c.current_limit_a && !(in_range(*c.current_limit_a, 0.0, 200.0) && *c.current_limit_a > 0)) {
    return fail("current_limit_a must be above 0 and at most 200 A");
  }
  if (!in_range(c.current_trip_s, 0.0, 60.0) || c.current_trip_s == 0.0) {
    return fail("current_trip_s must be above 0 and at most 60 s");
  }
  if (c.temperature_limit_c && !in_range(*c.temperature_limit_c, 0.0, 200.0)) {
    return fail("temperature_limit_c must be 0 to 200 °C");
  }
  if (!in_range(c.temperature_hysteresis_c, 0.0, 50.0)) {
    return fail("temperature_hysteresis_c must be 0 to 50 °C");
  }
  return c;
}

void MotorTrips::take(const MotorReadings& readings, double now_s) {
  if (readings.driver_fault) driver_fault_ = *readings.driver_fault;
  if (readings.temperature_c && config_.temperature_limit_c) {
    temperature_c_ = readings.temperature_c;
  }
  if (!readings.current_a || !config_.current_limit_a) return;
  current_a_ = readings.current_a;
  if (*current_a_ > *config_.current_limit_a) {
    if (!over_current_since_s_) over_current_since_s_ = now_s;
  } else {
    over_current_since_s_.reset();  // NaN too: it trips as a bad reading instead
  }
}

void MotorTrips::trip(MotorTrip kind, std::string what) {
  trip_ = kind;
  reason_ = config_.axis + ": " + std::move(what);
}

void MotorTrips::check(double now_s) {
  if (driver_fault_) {
    trip(MotorTrip::DriverFault, "motor driver reports a fault");
  } else if (temperature_c_ && std::isnan(*temperature_c_)) {
    trip(MotorTrip::BadReading, "motor temperature reading is not a number");
  } else if (current_a_ && std::isnan(*current_a_)) {
    trip(MotorTrip::BadReading, "motor current reading is not a number");
  } else if (temperature_c_ && *temperature_c_ > *config_.temperature_limit_c) {
    trip(MotorTrip::Temperature, "motor temperature " + celsius(*temperature_c_) + " above " +
                                     format_number(*config_.temperature_limit_c) + " °C");
  } else if (over_current_since_s_ && now_s - *over_current_since_s_ >= config_.current_trip_s) {
    trip(MotorTrip::Current, "motor current " + format_fixed(*current_a_, 1) + " A above " +
                                 format_number(*config_.current_limit_a) + " A for " +
                                 seconds_text(now_s - *over_current_since_s_) + " s");
  }
}

bool MotorTrips::update(const MotorReadings& readings, double now_s) {
  take(readings, now_s);
  if (trip_ == MotorTrip::None) {
    if (!std::isfinite(now_s)) {
      trip(MotorTrip::BadReading, "motor protection given a time that is not a number");
    } else {
      check(now_s);
    }
  }
  return trip_ == MotorTrip::None;
}

std::optional<std::string> MotorTrips::still_there() const {
  if (driver_fault_) return config_.axis + ": the motor driver still reports a fault";
  if (temperature_c_) {
    const double limit = *config_.temperature_limit_c;
    const double clear_below = limit - config_.temperature_hysteresis_c;
    if (!(*temperature_c_ < clear_below)) {
      return config_.axis + ": motor temperature " + celsius(*temperature_c_) +
             " is not yet below " + format_number(clear_below) + " °C (the " +
             format_number(limit) + " °C limit less " +
             format_number(config_.temperature_hysteresis_c) + " °C)";
    }
  }
  if (current_a_ && !(*current_a_ <= *config_.current_limit_a)) {
    return config_.axis + ": motor current " + format_fixed(*current_a_, 1) + " A is not below " +
           format_number(*config_.current_limit_a) + " A";
  }
  return std::nullopt;
}

std::optional<std::string> MotorTrips::reset() {
  if (trip_ == MotorTrip::None) return std::nullopt;
  if (auto why = still_there()) return why;
  trip_ = MotorTrip::None;
  reason_.clear();
  over_current_since_s_.reset();
  return std::nullopt;
}

}  // namespace azt::control
