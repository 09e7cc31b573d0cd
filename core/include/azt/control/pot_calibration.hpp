#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "azt/control/actuator_geometry.hpp"
#include "azt/ports/axis_sensor.hpp"
#include "azt/util/result.hpp"

namespace azt::control {

// Potentiometer position inputs (seed 002: "0 - 5 V for 0 - 360 degrees azimuth, 0 - 1.25 V for
// 0 - 90 degrees elevation", a 3-turn pot on a 3:1 chain and a 1-turn pot, read by the BX-24's
// 10-bit ADC; seed 003: a PIC16F870's 10-bit ADC behind a Yaesu G-5400/5600). ADC counts become
// degrees through a two-point calibration; open or shorted wipers are reported, not turned into
// plausible angles.

/// An ADC channel: `bits` of resolution over 0..vref_v, with the ideal transfer function
/// code = V / vref × 2^bits, so one count is vref / 2^bits (seed 002: "360/1024 or 0.35 degree"
/// for 10 bits over the full turn) and the largest code, 2^bits − 1, is reached just below vref.
struct AdcSpec {
  std::uint8_t bits = 10;
  double vref_v = 5.0;

  /// Validates: 8–24 bits, finite vref > 0.
  static Result<AdcSpec> make(int bits, double vref_v);

  /// 2^bits − 1: the largest code the converter can return.
  [[nodiscard]] std::int32_t max_counts() const;
  /// The (unrounded) count a voltage corresponds to.
  [[nodiscard]] double counts_from_volts(double volts) const;
};

/// BasicX BX-24 built-in ADC (seed 002): 10 bits, 5 V reference.
inline constexpr AdcSpec kAdcBx24{10, 5.0};
/// MCP3208 on SPI with its reference at 5 V: 12 bits.
inline constexpr AdcSpec kAdcMcp3208At5V{12, 5.0};
/// ADS1115 single-ended at PGA ±6.144 V (so a 5 V pot fits): the 16-bit signed result leaves 15
/// bits for positive inputs, 187.5 µV per count (ADS1115 datasheet, table "Full-Scale Range").
inline constexpr AdcSpec kAdcAds1115Fsr6V144{15, 6.144};

/// Two calibration points (counts, degrees) and the straight line through them. A pot wired the
/// other way round simply has deg_b < deg_a. Counts are real numbers: a point may be the nominal
/// count of a voltage (5 V on a 10-bit 5 V ADC is 1024, one past the largest code). The default
/// is seed 002's azimuth on the BX-24: 0 V → 0°, 5 V → 360°.
struct PotCalibration {
  double counts_a = 0.0;
  double deg_a = 0.0;
  double counts_b = 1024.0;
  double deg_b = 360.0;

  /// Validates: all finite, distinct counts, distinct angles.
  static Result<PotCalibration> make(double counts_a, double deg_a, double counts_b, double deg_b);
  /// The same from the voltages the seed's procedure adjusts ("Adjust the pot … for EXACTLY 0
  /// volts", "verify your pot is supplying as close to 1.25 volts as possible").
  static Result<PotCalibration> from_volts(const AdcSpec& adc, double volts_a, double deg_a,
                                           double volts_b, double deg_b);
  /// A multi-turn pot on a gear: its `pot_turns` of electrical travel span 0..supply_v, and it
  /// turns `pot_turns_per_axis_turn` times per turn of the axis (seed 002: a 3-turn pot on a 3:1
  /// chain, so 0–5 V is 0–360°; a 10-turn pot at 8:1 spans 450°). `deg_at_zero_v` is the axis
  /// angle where the wiper reads 0 V.
  static Result<PotCalibration> geared(const AdcSpec& adc, double supply_v, double pot_turns,
                                       double pot_turns_per_axis_turn, double deg_at_zero_v);

  [[nodiscard]] double to_deg(double counts) const;
  /// The inverse (for simulated pots and for checking limits in counts).
  [[nodiscard]] double to_counts(double deg) const;
};

/// The mean of the last `window` integer samples (1–64), kept as an exact integer sum so that it
/// never drifts however long it runs. Averaging N samples taken every T seconds delays a moving
/// axis by (N − 1)·T/2: keep N small on fast axes.
class MovingAverage {
 public:
  static constexpr std::size_t kCapacity = 64;

  /// `window` is clamped to 1..kCapacity.
  explicit MovingAverage(std::size_t window);

  void push(std::int32_t sample);
  void reset();

  [[nodiscard]] std::size_t window() const { return window_; }
  /// Samples held (grows to window() after a reset).
  [[nodiscard]] std::size_t count() const { return count_; }
  /// The mean of the samples held; NaN when there are none.
  [[nodiscard]] double mean() const;

 private:
  std::array<std::int32_t, kCapacity> samples_{};
  std::size_t window_ = 1;
  std::size_t next_ = 0;
  std::size_t count_ = 0;
  std::int64_t sum_ = 0;
};

/// Why a pot reading is not an angle.
enum class PotStatus : std::uint8_t {
  Ok,
  OutOfRange,  ///< the count is outside 0..2^bits − 1: not something this ADC can return
  OpenLow,     ///< below the open-wire guard: broken wiper pulled down, or shorted to ground
  OpenHigh,    ///< above the guard: broken ground end, or wiper shorted to the supply
  /// A pot on a linear actuator reads a length outside the actuator's stroke: a calibration or
  /// wiring error, since the actuator cannot be there (actuator_geometry.hpp).
  OutsideStroke,
};

std::string_view to_string(PotStatus status);

struct PotReading {
  PotStatus status = PotStatus::Ok;
  double deg = 0.0;  ///< NaN unless ok(): a broken wiper never reads as an angle
  [[nodiscard]] bool ok() const { return status == PotStatus::Ok; }
};

/// A pot reading as its axis sensor reports it, on Linux and in the simulation alike: an angle
/// taken at `now_s`, or an error naming the pot (`what`) with the status's words.
Result<ports::SensorReading> pot_sensor_reading(const PotReading& r, double now_s,
                                                std::string_view what);

/// One pot channel: ADC, calibration, guards, averaging.
///
/// The guards catch broken wiring: with a pull-down (or pull-up) on the wiper, an open wiper reads
/// 0 (or full scale). That only works if the working range stays clear of the rails — the seed's
/// "0 V = 0°" adjustment makes a broken wiper and the counter-clockwise stop look the same; set
/// the pot a few percent in from the rail and put the guard between.
struct PotInputConfig {
  AdcSpec adc;
  PotCalibration calibration;
  std::optional<std::int32_t> open_below_counts;  ///< samples below this are OpenLow
  std::optional<std::int32_t> open_above_counts;  ///< samples above this are OpenHigh
  std::size_t average_samples = 1;                ///< 1..MovingAverage::kCapacity
  /// A pot on a linear actuator (a LINAK- or superjack-style actuator with a feedback pot): the
  /// pot measures length, not angle, so the calibration's two points are (counts, millimetres
  /// of actuator length), its deg_a and deg_b fields holding millimetres, and each averaged
  /// length becomes the mount angle through the triangle. Empty: the line gives degrees.
  std::optional<ActuatorGeometryConfig> actuator;

  /// Validates: the ADC and the calibration, guards inside 0..max_counts with below < above,
  /// the averaging window, and the actuator's triangle when there is one.
  static Result<PotInputConfig> make(const PotInputConfig& c);

  /// The angle of one ADC count where it is coarsest: the line's degrees per count, or on an
  /// actuator its millimetres per count times the stroke's largest degrees per millimetre
  /// (ActuatorGeometry::max_deg_per_mm). The controller's and the supervisor's step on such an
  /// axis. Precondition: make(*this).ok().
  [[nodiscard]] double max_deg_per_count() const;
};

class PotInput {
 public:
  /// Precondition: PotInputConfig::make(config).ok().
  explicit PotInput(const PotInputConfig& config);

  /// One ADC sample. A bad sample is reported at once and empties the average, so samples from
  /// before a wiring fault never mix with samples after it; the average refills from the next
  /// good sample (its first reading is that sample alone).
  PotReading push(std::int32_t counts);
  void reset() { average_.reset(); }

  [[nodiscard]] const PotInputConfig& config() const { return config_; }

 private:
  [[nodiscard]] PotStatus classify(std::int32_t counts) const;

  /// The averaged reading's angle: the line's, or the actuator's at the line's length.
  [[nodiscard]] PotReading angle_of(double counts) const;

  PotInputConfig config_;
  std::optional<ActuatorGeometry> actuator_;
  MovingAverage average_;
};

}  // namespace azt::control
