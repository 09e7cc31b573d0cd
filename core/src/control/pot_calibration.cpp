#include "azt/control/pot_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>

namespace azt::control {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool all_finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

Result<AdcSpec> AdcSpec::make(int bits, double vref_v) {
  // 24 bits is the widest common converter (ADS1256); counts stay exact in int32 and double.
  if (bits < 8 || bits > 24) return fail("ADC resolution must be 8 to 24 bits");
  if (!std::isfinite(vref_v) || vref_v <= 0.0) {
    return fail("ADC reference voltage must be finite and positive");
  }
  return AdcSpec{static_cast<std::uint8_t>(bits), vref_v};
}

std::int32_t AdcSpec::max_counts() const {
  return static_cast<std::int32_t>((std::int64_t{1} << bits) - 1);
}

double AdcSpec::counts_from_volts(double volts) const {
  return volts / vref_v * std::ldexp(1.0, bits);
}

Result<PotCalibration> PotCalibration::make(double counts_a, double deg_a, double counts_b,
                                            double deg_b) {
  if (!all_finite({counts_a, deg_a, counts_b, deg_b})) {
    return fail("pot calibration points must be finite");
  }
  if (counts_a == counts_b) return fail("pot calibration points must have different counts");
  if (deg_a == deg_b) return fail("pot calibration points must have different angles");
  return PotCalibration{counts_a, deg_a, counts_b, deg_b};
}

Result<PotCalibration> PotCalibration::from_volts(const AdcSpec& adc, double volts_a, double deg_a,
                                                  double volts_b, double deg_b) {
  if (!AdcSpec::make(adc.bits, adc.vref_v)) return fail("invalid ADC for the pot calibration");
  return make(adc.counts_from_volts(volts_a), deg_a, adc.counts_from_volts(volts_b), deg_b);
}

Result<PotCalibration> PotCalibration::geared(const AdcSpec& adc, double supply_v, double pot_turns,
                                              double pot_turns_per_axis_turn,
                                              double deg_at_zero_v) {
  if (!all_finite({supply_v, pot_turns, pot_turns_per_axis_turn, deg_at_zero_v}) ||
      supply_v <= 0.0 || pot_turns <= 0.0 || pot_turns_per_axis_turn <= 0.0) {
    return fail("geared pot: supply, turns and gear ratio must be finite and positive");
  }
  // The pot's whole electrical travel, in axis degrees: its turns divided by the gear ratio.
  const double span_deg = 360.0 * pot_turns / pot_turns_per_axis_turn;
  return from_volts(adc, 0.0, deg_at_zero_v, supply_v, deg_at_zero_v + span_deg);
}

double PotCalibration::to_deg(double counts) const {
  return deg_a + (counts - counts_a) * (deg_b - deg_a) / (counts_b - counts_a);
}

double PotCalibration::to_counts(double deg) const {
  return counts_a + (deg - deg_a) * (counts_b - counts_a) / (deg_b - deg_a);
}

MovingAverage::MovingAverage(std::size_t window)
    : window_(std::clamp<std::size_t>(window, 1, kCapacity)) {}

void MovingAverage::push(std::int32_t sample) {
  if (count_ == window_) {
    sum_ -= samples_[next_];  // the oldest sample leaves the window
  } else {
    ++count_;
  }
  samples_[next_] = sample;
  sum_ += sample;
  next_ = (next_ + 1) % window_;
}

void MovingAverage::reset() {
  next_ = 0;
  count_ = 0;
  sum_ = 0;
}

double MovingAverage::mean() const {
  if (count_ == 0) return kNaN;
  return static_cast<double>(sum_) / static_cast<double>(count_);
}

std::string_view to_string(PotStatus status) {
  switch (status) {
    case PotStatus::Ok:
      return "ok";
    case PotStatus::OutOfRange:
      return "ADC count out of range";
    case PotStatus::OpenLow:
      return "pot reads below its guard (open wiper or short to ground)";
    case PotStatus::OpenHigh:
      return "pot reads above its guard (open ground or short to supply)";
    case PotStatus::OutsideStroke:
      return "pot reads a length outside the actuator's stroke (check pot_calibration_mm)";
  }
  return "unknown";
}

Result<ports::SensorReading> pot_sensor_reading(const PotReading& r, double now_s,
                                                std::string_view what) {
  if (r.ok()) return ports::SensorReading{ports::AxisSample{r.deg, now_s}};
  return fail(std::string(what) + ": " + std::string(to_string(r.status)));
}

Result<PotInputConfig> PotInputConfig::make(const PotInputConfig& c) {
  const auto adc = AdcSpec::make(c.adc.bits, c.adc.vref_v);
  if (!adc) return adc.error();
  const PotCalibration& k = c.calibration;
  if (const auto cal = PotCalibration::make(k.counts_a, k.deg_a, k.counts_b, k.deg_b); !cal) {
    return cal.error();
  }
  const std::int32_t top = c.adc.max_counts();
  const std::int32_t below = c.open_below_counts.value_or(0);
  const std::int32_t above = c.open_above_counts.value_or(top);
  if (below < 0 || below > top || above < 0 || above > top) {
    return fail("pot open-wire guards must be within 0.." + std::to_string(top) + " counts");
  }
  if (below >= above) return fail("pot open-wire guards leave no valid counts (below >= above)");
  if (c.average_samples < 1 || c.average_samples > MovingAverage::kCapacity) {
    return fail("pot averaging must be 1 to 64 samples");
  }
  if (c.actuator) {
    if (auto g = ActuatorGeometry::make(*c.actuator); !g) return g.error();
  }
  return c;
}

double PotInputConfig::max_deg_per_count() const {
  const double per_count = std::abs((calibration.deg_b - calibration.deg_a) /
                                    (calibration.counts_b - calibration.counts_a));
  if (!actuator) return per_count;
  return per_count * ActuatorGeometry(*actuator).max_deg_per_mm();  // millimetres per count
}

PotInput::PotInput(const PotInputConfig& config)
    : config_(config), average_(config.average_samples) {
  if (config.actuator) actuator_.emplace(*config.actuator);
}

PotReading PotInput::angle_of(double counts) const {
  const double value = config_.calibration.to_deg(counts);
  if (!actuator_) return PotReading{PotStatus::Ok, value};
  const auto angle = actuator_->angle_deg(value);  // the line's value is a length here
  if (!angle) return PotReading{PotStatus::OutsideStroke, kNaN};
  return PotReading{PotStatus::Ok, *angle};
}

PotStatus PotInput::classify(std::int32_t counts) const {
  if (counts < 0 || counts > config_.adc.max_counts()) return PotStatus::OutOfRange;
  if (config_.open_below_counts && counts < *config_.open_below_counts) return PotStatus::OpenLow;
  if (config_.open_above_counts && counts > *config_.open_above_counts) return PotStatus::OpenHigh;
  return PotStatus::Ok;
}

PotReading PotInput::push(std::int32_t counts) {
  const PotStatus status = classify(counts);
  if (status != PotStatus::Ok) {
    average_.reset();
    return PotReading{status, kNaN};
  }
  average_.push(counts);
  return angle_of(average_.mean());
}

}  // namespace azt::control
