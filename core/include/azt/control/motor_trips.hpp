#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "azt/util/result.hpp"

namespace azt::control {

// Protection at the motor: a stalled or overloaded motor draws current and heats up long before
// the position supervisor's stall check (seconds of no motion) sees anything, and a driver that
// has shut itself down says so on a pin. SatNOGS' rotator firmware stops on motor
// over-temperature and on a driver fault (its error bits, libraries/globals.h, motor_error). A
// trip stops the axis and latches: only the operator's reset clears it, and only once the
// reading is back (a motor that cooled by 1 °C is still too hot).

/// The IBT-2's current sense: each BTS7960 half-bridge sources a current proportional to its
/// load current out of its IS pin, I_IS = I_L / k_ILIS, turned into a voltage by a resistor
/// R_IS to ground and read by an ADC. k_ILIS is 8500 typical (BTS7960B data sheet rev 1.1,
/// 4.4.6, measured with R_IS = 1 kΩ: 8.5 A per volt), but its spread is wide (3000 to 14000 at
/// 5 A): measure a known current and set amps_per_volt from it. In a fault the pin sources a
/// fixed 4–7 mA (4.4.7): several volts, which reads as a large current and trips after
/// current_trip_s.
struct CurrentSense {
  double amps_per_volt = 8.5;  ///< k_ILIS / R_IS
  double offset_v = 0.0;       ///< the IS voltage at zero current (leakage; read it at rest)

  /// Validates: amps_per_volt finite in (0, 1000], offset_v finite in [0, 5] V.
  static Result<CurrentSense> make(const CurrentSense& c);
  /// The motor current for an IS voltage (never negative; NaN stays NaN).
  [[nodiscard]] double amps(double sense_v) const;
};

/// What tripped.
enum class MotorTrip : std::uint8_t {
  None,
  Current,      ///< above current_limit_a for current_trip_s
  Temperature,  ///< above temperature_limit_c
  DriverFault,  ///< the driver's fault input went active
  BadReading,   ///< a current or temperature reading that is not a number
};

std::string_view to_string(MotorTrip trip);

struct MotorTripsConfig {
  std::string axis = "az";  ///< the axis's name, first in every reason ("az: …")
  /// Trip above this current (A) held for current_trip_s; empty: no current input.
  std::optional<double> current_limit_a;
  /// Long enough for the start current (a DC motor draws several times its running current
  /// for the first tenths of a second), short enough to save a stalled motor. (0, 60] s.
  double current_trip_s = 0.5;
  /// Trip above this motor temperature (°C); empty: no temperature input.
  std::optional<double> temperature_limit_c;
  /// A temperature trip may be reset only below limit − hysteresis (°C), [0, 50].
  double temperature_hysteresis_c = 5.0;

  /// Validates every field; errors name it.
  static Result<MotorTripsConfig> make(const MotorTripsConfig& c);
};

/// This tick's readings; an empty field is "no new reading" (the last one stands).
struct MotorReadings {
  std::optional<double> current_a;
  std::optional<double> temperature_c;
  std::optional<bool> driver_fault;  ///< the driver's fault line, true = fault
};

/// The motor protection of one axis. Pure: time is a parameter (seconds of a monotonic clock).
///
/// Plugged in by DrivenAxis (driven_axis.hpp), each tick: update() with the readings that
/// arrived (ADC channels through the sensors already supported: the IS voltage through
/// CurrentSense::amps(); a temperature sensor in °C; a GPIO line); when it returns false the
/// axis stops at once (duty 0, the brake applied, as a supervisor fault) and shows reason().
/// The operator's clear calls reset(); its words, when it refuses, go back to the operator.
class MotorTrips {
 public:
  /// Precondition: MotorTripsConfig::make(config).ok().
  explicit MotorTrips(MotorTripsConfig config) : config_(std::move(config)) {}

  /// One tick at `now_s`. Returns whether the motor may run (false once tripped, until reset).
  bool update(const MotorReadings& readings, double now_s);
  /// The operator's reset. Empty: cleared (or nothing was tripped). Otherwise the words why the
  /// trip stays: its cause is still there.
  [[nodiscard]] std::optional<std::string> reset();

  [[nodiscard]] MotorTrip tripped() const { return trip_; }
  /// "az: motor current 12.3 A above 10 A for 0.5 s"; empty while not tripped.
  [[nodiscard]] const std::string& reason() const { return reason_; }
  [[nodiscard]] std::optional<double> last_current_a() const { return current_a_; }
  [[nodiscard]] std::optional<double> last_temperature_c() const { return temperature_c_; }
  [[nodiscard]] const MotorTripsConfig& config() const { return config_; }

 private:
  void take(const MotorReadings& readings, double now_s);
  void check(double now_s);
  void trip(MotorTrip kind, std::string what);
  [[nodiscard]] std::optional<std::string> still_there() const;

  MotorTripsConfig config_;
  MotorTrip trip_ = MotorTrip::None;
  std::string reason_;
  std::optional<double> current_a_;
  std::optional<double> temperature_c_;
  bool driver_fault_ = false;
  std::optional<double> over_current_since_s_;
};

}  // namespace azt::control
