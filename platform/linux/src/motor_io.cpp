#include "azt/linux/motor_io.hpp"

#include <functional>
#include <optional>
#include <utility>

#include "azt/linux/adc_devices.hpp"
#include "azt/proto/adc_frames.hpp"

namespace azt::linux_os {
namespace {

class GpioBrakeLine final : public ports::BrakeLine {
 public:
  explicit GpioBrakeLine(std::unique_ptr<GpioOutput> line) : line_(std::move(line)) {}
  GpioBrakeLine(const GpioBrakeLine&) = delete;
  GpioBrakeLine& operator=(const GpioBrakeLine&) = delete;
  GpioBrakeLine(GpioBrakeLine&&) = delete;
  GpioBrakeLine& operator=(GpioBrakeLine&&) = delete;
  ~GpioBrakeLine() override { (void)line_->set(false); }

  Result<bool> apply(double /*now_s*/, bool release) override {
    // Written only on a change: the line stays as it is between a brake's transitions.
    if (line_->active() == release) return true;
    auto r = line_->set(release);
    if (!r) return fail(describe() + ": " + r.error().message);
    return true;
  }
  void off(double /*now_s*/) override { (void)line_->set(false); }
  [[nodiscard]] std::string describe() const override {
    return "brake on " + linux_os::describe(line_->spec());
  }

 private:
  std::unique_ptr<GpioOutput> line_;
};

/// The volts at one of the motor's ADC channels this tick; nullopt: nothing new (an ADS1115
/// channel between its turns).
using ChannelVolts = std::function<Result<std::optional<double>>(unsigned channel, double now_s)>;

class AdcMotorSensor final : public ports::MotorSensor {
 public:
  AdcMotorSensor(ChannelVolts volts, const MotorAdcInputs& inputs, std::unique_ptr<GpioInput> fault,
                 std::string what)
      : volts_(std::move(volts)),
        inputs_(inputs),
        fault_(std::move(fault)),
        what_(std::move(what)) {}

  Result<ports::MotorSample> read(double now_s) override {
    ports::MotorSample sample;
    if (inputs_.current_channel) {
      auto v = volts(*inputs_.current_channel, now_s);
      if (!v) return v.error();
      if (v.value()) sample.current_a = inputs_.current.amps(*v.value());
    }
    if (inputs_.temperature_channel) {
      auto v = volts(*inputs_.temperature_channel, now_s);
      if (!v) return v.error();
      if (v.value()) {
        sample.temperature_c =
            inputs_.temperature_offset_c + *v.value() * inputs_.temperature_c_per_v;
      }
    }
    if (fault_) sample.driver_fault = fault_->active();
    return sample;
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  Result<std::optional<double>> volts(unsigned channel, double now_s) {
    auto v = volts_(channel, now_s);
    if (!v) return fail(what_ + ": " + v.error().message);
    return v;
  }

  ChannelVolts volts_;
  MotorAdcInputs inputs_;
  std::unique_ptr<GpioInput> fault_;
  std::string what_;
};

}  // namespace

std::unique_ptr<ports::BrakeLine> make_gpio_brake_line(std::unique_ptr<GpioOutput> line) {
  return std::make_unique<GpioBrakeLine>(std::move(line));
}

std::unique_ptr<ports::MotorSensor> make_motor_sensor(std::unique_ptr<SpiBus> bus,
                                                      const MotorAdcInputs& inputs,
                                                      std::unique_ptr<GpioInput> fault,
                                                      std::string what) {
  // Shared by the reading function; the sensor is its only owner.
  std::shared_ptr<SpiBus> spi = std::move(bus);
  const double vref_v = inputs.vref_v;
  ChannelVolts volts = [spi, vref_v](unsigned channel,
                                     double /*now_s*/) -> Result<std::optional<double>> {
    Mcp3008Reader adc(*spi);
    auto code = adc.read(channel);
    if (!code) return code.error();
    return std::optional<double>{static_cast<double>(code.value()) * vref_v / 1024.0};
  };
  return std::make_unique<AdcMotorSensor>(std::move(volts), inputs, std::move(fault),
                                          std::move(what));
}

std::unique_ptr<ports::MotorSensor> make_ads1115_motor_sensor(std::shared_ptr<Ads1115Chip> chip,
                                                              const MotorAdcInputs& inputs,
                                                              std::unique_ptr<GpioInput> fault,
                                                              std::string what) {
  const double volts_per_count = proto::ads1115_volts_per_count(proto::Ads1115Range::Fs4V096);
  ChannelVolts volts = [chip = std::move(chip), volts_per_count](
                           unsigned channel, double now_s) -> Result<std::optional<double>> {
    auto code = chip->step(channel, now_s);
    if (!code) return code.error();
    if (!code.value()) return std::optional<double>{};
    return std::optional<double>{static_cast<double>(*code.value()) * volts_per_count};
  };
  return std::make_unique<AdcMotorSensor>(std::move(volts), inputs, std::move(fault),
                                          std::move(what));
}

}  // namespace azt::linux_os
