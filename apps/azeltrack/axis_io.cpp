#include "axis_io.hpp"

#include <chrono>
#include <cmath>
#include <thread>

#include "azt/control/pot_calibration.hpp"
#include "azt/control/setpoint_drive.hpp"
#include "azt/linux/adc_devices.hpp"
#include "azt/linux/mcp41010.hpp"
#include "azt/linux/pwm_hbridge.hpp"
#include "cli_error.hpp"

namespace azt::app {
namespace {

/// An IBT-2: the bridge's PWMs, and its enables when wired to a GPIO line. The enables go high
/// with the first drive and low on off(), so a stop or a fault also cuts the bridge in hardware.
class PwmActuator final : public AxisActuator {
 public:
  PwmActuator(linux_os::PwmHBridge bridge, std::unique_ptr<linux_os::GpioOutput> enable,
              std::string what)
      : bridge_(std::move(bridge)), enable_(std::move(enable)), what_(std::move(what)) {}
  ~PwmActuator() override { off(0.0); }
  PwmActuator(const PwmActuator&) = delete;
  PwmActuator& operator=(const PwmActuator&) = delete;
  PwmActuator(PwmActuator&&) = delete;
  PwmActuator& operator=(PwmActuator&&) = delete;

  Result<bool> apply(double now_s, double duty, std::optional<double> /*setpoint*/) override {
    if (enable_ && duty != 0.0 && !enable_->active()) {
      if (auto r = enable_->set(true); !r) {
        off(now_s);
        return r.error();
      }
    }
    return bridge_.apply(now_s, duty);
  }
  void off(double now_s) override {
    (void)bridge_.disable(now_s);
    if (enable_) (void)enable_->set(false);
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  linux_os::PwmHBridge bridge_;
  std::unique_ptr<linux_os::GpioOutput> enable_;
  std::string what_;
};

/// Forward/reverse relays (a G-5400/5600 box's CW/CCW, seed 002's rotor) or power + polarity
/// (seed 002's actuator). RelayDrive (in the station) already keeps the minimum on-time and the
/// reversal dead time; this only switches, the releasing line always first.
class RelayActuator final : public AxisActuator {
 public:
  RelayActuator(std::unique_ptr<linux_os::GpioOutput> a, std::unique_ptr<linux_os::GpioOutput> b,
                bool power_polarity, const control::PowerPolarityConfig& pp, std::string what)
      : a_(std::move(a)),
        b_(std::move(b)),
        power_polarity_(power_polarity),
        relays_(pp),
        what_(std::move(what)) {}
  ~RelayActuator() override { off(0.0); }
  RelayActuator(const RelayActuator&) = delete;
  RelayActuator& operator=(const RelayActuator&) = delete;
  RelayActuator(RelayActuator&&) = delete;
  RelayActuator& operator=(RelayActuator&&) = delete;

  Result<bool> apply(double now_s, double duty, std::optional<double> /*setpoint*/) override {
    const auto command = duty > 0.0   ? control::RelayCommand::Forward
                         : duty < 0.0 ? control::RelayCommand::Reverse
                                      : control::RelayCommand::Off;
    if (power_polarity_) {
      // a: power, b: polarity. The core guarantees the polarity only moves with power off.
      const control::PowerPolarity out = relays_.update(command, now_s);
      if (!out.power) return set_all({{a_.get(), false}, {b_.get(), out.reverse}}, now_s);
      return set_all({{b_.get(), out.reverse}, {a_.get(), true}}, now_s);
    }
    // a: forward, b: reverse; the one going off is written first.
    const bool fwd = command == control::RelayCommand::Forward;
    const bool rev = command == control::RelayCommand::Reverse;
    if (fwd) return set_all({{b_.get(), false}, {a_.get(), true}}, now_s);
    return set_all({{a_.get(), false}, {b_.get(), rev}}, now_s);
  }

  void off(double now_s) override {
    relays_.halt(now_s);
    (void)a_->set(false);
    if (!power_polarity_) (void)b_->set(false);  // the polarity relay keeps its state, unpowered
  }

  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  Result<bool> set_all(std::initializer_list<std::pair<linux_os::GpioOutput*, bool>> lines,
                       double now_s) {
    for (const auto& [line, on] : lines) {
      if (line->active() == on) continue;
      if (auto r = line->set(on); !r) {
        off(now_s);
        return r.error();
      }
    }
    return true;
  }

  std::unique_ptr<linux_os::GpioOutput> a_;
  std::unique_ptr<linux_os::GpioOutput> b_;
  bool power_polarity_;
  control::PowerPolarityRelays relays_;
  std::string what_;
};

/// Seed 001: an MCP41010 replaces the rotator box's control pot; the box closes the loop. Codes
/// are written only when they change, and again after a write failed (the pot may have lost
/// power and woken at mid-scale).
class PotActuator final : public AxisActuator {
 public:
  PotActuator(std::unique_ptr<linux_os::SpiBus> bus, const control::SetpointCalibration& cal,
              std::string what)
      : bus_(std::move(bus)), pot_(*bus_), drive_(cal), what_(std::move(what)) {}

  Result<bool> apply(double /*now_s*/, double /*duty*/, std::optional<double> setpoint) override {
    if (!setpoint) return true;
    last_setpoint_ = setpoint;
    const control::SetpointUpdate u = drive_.update(*setpoint);
    if (!u.send) return true;
    if (auto r = pot_.write(*u.send); !r) {
      drive_.force_resend();
      return r.error();
    }
    return true;
  }

  /// The box holds the rotator at its setpoint: stopping is sending where it stands, which the
  /// station has already made the setpoint; here it is only written again.
  void off(double now_s) override {
    drive_.force_resend();
    if (last_setpoint_) (void)apply(now_s, 0.0, last_setpoint_);
  }

  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  std::unique_ptr<linux_os::SpiBus> bus_;
  linux_os::Mcp41010Writer pot_;
  control::SetpointDrive drive_;
  std::optional<double> last_setpoint_;
  std::string what_;
};

class Mcp3008Sensor final : public AxisSensor {
 public:
  Mcp3008Sensor(std::unique_ptr<linux_os::SpiBus> bus, unsigned channel,
                const control::PotInputConfig& pot, std::string what)
      : bus_(std::move(bus)), adc_(*bus_), channel_(channel), pot_(pot), what_(std::move(what)) {}
  Result<double> read() override {
    auto code = adc_.read(channel_);
    if (!code) {
      pot_.reset();
      return code.error();
    }
    return angle(pot_.push(code.value()), what_);
  }
  [[nodiscard]] std::string describe() const override { return what_; }

  static Result<double> angle(const control::PotReading& r, const std::string& what) {
    if (r.ok()) return r.deg;
    return fail(what + ": " + std::string(control::to_string(r.status)));
  }

 private:
  std::unique_ptr<linux_os::SpiBus> bus_;
  linux_os::Mcp3008Reader adc_;
  unsigned channel_;
  control::PotInput pot_;
  std::string what_;
};

class Ads1115Sensor final : public AxisSensor {
 public:
  Ads1115Sensor(std::unique_ptr<linux_os::I2cBus> bus, const HardwareAxisConfig& a,
                std::function<void()> wait, std::string what)
      : bus_(std::move(bus)),
        adc_(*bus_, a.adc_address, proto::Ads1115Range::Fs4V096, std::move(wait)),
        channel_(a.adc_channel),
        pot_(a.pot),
        what_(std::move(what)) {}
  Result<double> read() override {
    auto code = adc_.read(channel_);
    if (!code) {
      pot_.reset();
      return code.error();
    }
    return Mcp3008Sensor::angle(pot_.push(code.value()), what_);
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  std::unique_ptr<linux_os::I2cBus> bus_;
  linux_os::Ads1115Reader adc_;
  unsigned channel_;
  control::PotInput pot_;
  std::string what_;
};

std::unique_ptr<linux_os::GpioOutput> output_line(HardwarePorts& ports,
                                                  const linux_os::GpioLineSpec& spec) {
  if (ports.gpio == nullptr) throw UsageError(spec.key + ": no GPIO provider");
  auto line = ports.gpio->output(spec, false);  // released until the station asks
  if (!line) throw UsageError(line.error().message);
  return std::move(line).value();
}

}  // namespace

HardwarePorts HardwarePorts::linux_devices(linux_os::GpioProvider* gpio) {
  HardwarePorts p;
  p.gpio = gpio;
  p.open_spi = [](const std::string& path,
                  std::uint32_t hz) -> Result<std::unique_ptr<linux_os::SpiBus>> {
    auto bus = linux_os::SpidevBus::open(path, hz);
    if (!bus) return bus.error();
    return std::unique_ptr<linux_os::SpiBus>(
        std::make_unique<linux_os::SpidevBus>(std::move(bus).value()));
  };
  p.open_i2c = [](const std::string& path) -> Result<std::unique_ptr<linux_os::I2cBus>> {
    auto bus = linux_os::I2cDevBus::open(path);
    if (!bus) return bus.error();
    return std::unique_ptr<linux_os::I2cBus>(
        std::make_unique<linux_os::I2cDevBus>(std::move(bus).value()));
  };
  p.adc_wait = linux_os::sleep_one_ms;
  return p;
}

std::unique_ptr<AxisActuator> make_actuator(const HardwareAxisConfig& a, const PwmConfig& pwm,
                                            HardwarePorts& ports) {
  if (a.drive == "relay") {
    const bool pp = a.relay_power.has_value();
    auto first = output_line(ports, pp ? *a.relay_power : *a.relay_forward);
    auto second = output_line(ports, pp ? *a.relay_polarity : *a.relay_reverse);
    return std::make_unique<RelayActuator>(
        std::move(first), std::move(second), pp,
        control::PowerPolarityConfig{a.relay.reversal_dead_s, a.polarity_settle_s},
        pp ? "relays (power + polarity)" : "relays (forward/reverse)");
  }
  if (a.drive == "pot") {
    auto bus = ports.open_spi(a.spi_device, a.spi_hz);
    if (!bus) throw UsageError(a.key("spi_device") + ": " + bus.error().message);
    return std::make_unique<PotActuator>(std::move(bus).value(), a.wiper,
                                         "MCP41010 on " + a.spi_device);
  }
  linux_os::PwmHBridgeConfig c;
  c.chip_dir = pwm.chip_dir;
  c.rpwm_channel = a.name == "az" ? pwm.az_rpwm : pwm.el_rpwm;
  c.lpwm_channel = a.name == "az" ? pwm.az_lpwm : pwm.el_lpwm;
  c.frequency_hz = pwm.frequency_hz;
  c.dead_time_s = pwm.dead_time_s;
  auto bridge = linux_os::PwmHBridge::open(c);
  if (!bridge) {
    throw UsageError(std::string("[pwm] ") + (a.name == "az" ? "azimuth" : "elevation") + ": " +
                     bridge.error().message);
  }
  std::unique_ptr<linux_os::GpioOutput> enable;
  if (a.enable) {
    try {
      enable = output_line(ports, *a.enable);
    } catch (const UsageError&) {
      (void)bridge.value().disable(0.0);
      throw;
    }
  }
  return std::make_unique<PwmActuator>(
      std::move(bridge).value(), std::move(enable),
      a.enable ? "IBT-2 on sysfs PWM, enables on GPIO" : "IBT-2 on sysfs PWM");
}

std::unique_ptr<AxisSensor> make_adc_sensor(const HardwareAxisConfig& a, HardwarePorts& ports) {
  const std::string what = a.name + " pot (" + a.sensor + " " + a.adc_device + " channel " +
                           std::to_string(a.adc_channel) + ")";
  if (a.sensor == "mcp3008") {
    auto bus = ports.open_spi(a.adc_device, 1'000'000);
    if (!bus) throw UsageError(a.key("adc_device") + ": " + bus.error().message);
    return std::make_unique<Mcp3008Sensor>(std::move(bus).value(), a.adc_channel, a.pot, what);
  }
  auto bus = ports.open_i2c(a.adc_device);
  if (!bus) throw UsageError(a.key("adc_device") + ": " + bus.error().message);
  return std::make_unique<Ads1115Sensor>(std::move(bus).value(), a, ports.adc_wait, what);
}

}  // namespace azt::app
