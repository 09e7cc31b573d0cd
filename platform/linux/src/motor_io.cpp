#include "azt/linux/motor_io.hpp"

#include <utility>

#include "azt/linux/adc_devices.hpp"

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

class AdcMotorSensor final : public ports::MotorSensor {
 public:
  AdcMotorSensor(std::unique_ptr<SpiBus> bus, const MotorAdcInputs& inputs,
                 std::unique_ptr<GpioInput> fault, std::string what)
      : bus_(std::move(bus)), inputs_(inputs), fault_(std::move(fault)), what_(std::move(what)) {}

  Result<ports::MotorSample> read(double /*now_s*/) override {
    ports::MotorSample sample;
    if (inputs_.current_channel) {
      auto v = volts(*inputs_.current_channel);
      if (!v) return v.error();
      sample.current_a = inputs_.current.amps(v.value());
    }
    if (inputs_.temperature_channel) {
      auto v = volts(*inputs_.temperature_channel);
      if (!v) return v.error();
      sample.temperature_c = inputs_.temperature_offset_c + v.value() * inputs_.temperature_c_per_v;
    }
    if (fault_) sample.driver_fault = fault_->active();
    return sample;
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  Result<double> volts(unsigned channel) {
    Mcp3008Reader adc(*bus_);
    auto code = adc.read(channel);
    if (!code) return fail(what_ + ": " + code.error().message);
    return static_cast<double>(code.value()) * inputs_.vref_v / 1024.0;
  }

  std::unique_ptr<SpiBus> bus_;
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
  return std::make_unique<AdcMotorSensor>(std::move(bus), inputs, std::move(fault),
                                          std::move(what));
}

}  // namespace azt::linux_os
