#include "antenna/axis_io.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "azt/control/pot_calibration.hpp"
#include "azt/control/setpoint_drive.hpp"
#include "azt/linux/adc_devices.hpp"
#include "azt/linux/mcp41010.hpp"
#include "azt/linux/pwm_hbridge.hpp"
#include "common/usage_error.hpp"

namespace azt::app {

/// One ADS1115, converting for the one or two axes whose pots are wired to it, in steps across
/// control ticks: a conversion takes about 8 ms at 128 samples/s and no handler may block the
/// loop, so no tick waits for one. At each tick an axis polls its channel's conversion, started
/// on an earlier tick, once; when it is done the axis fetches the result and starts the next
/// channel's conversion (its own again when it is alone on the chip), which is done long before
/// the next tick (20 Hz by default: 50 ms). So an axis alone on a chip costs 5 I2C messages a
/// tick (poll: pointer + read, fetch: pointer + read, start: one write) and no wait.
///
/// The price is latency: a reading reaches the station one tick after its conversion started
/// (≤ tick_s; two ticks with two axes on the chip, each then read every other tick), stamped
/// with the tick that fetched it, as the hub's frames are stamped when they arrive. Accepted:
/// one tick adds at most rate × tick_s of lag (3 deg/s × 50 ms = 0.15 deg), less than the pot's
/// moving average already holds (average_samples = 4: 1.5 ticks) and well inside a relay
/// window of 1 deg. Two axes on one chip need tick_hz > 15: the backend passes both axes on
/// stamped with the older, up to two ticks old then, and the stale limit is 200 ms less a tick.
class Ads1115Chip {
 public:
  /// Polls, one a tick, before a conversion counts as lost: 3 ticks are at least 15 ms at the
  /// fastest tick (200 Hz), more than 1.7 conversions even with the chip's oscillator 10% slow.
  /// At 20 Hz the first poll finds the conversion done.
  static constexpr unsigned kMaxPolls = 3;

  Ads1115Chip(std::unique_ptr<linux_os::I2cBus> bus, std::uint8_t address)
      : bus_(std::move(bus)), adc_(*bus_, address, proto::Ads1115Range::Fs4V096) {}

  [[nodiscard]] bool has_channel(unsigned channel) const {
    return std::find(channels_.begin(), channels_.end(), channel) != channels_.end();
  }
  void add_channel(unsigned channel) { channels_.push_back(channel); }

  /// The tick `now_s` of `channel`'s axis: its new code, nullopt while there is none (the first
  /// tick, a conversion still running, the other axis's turn), or an error (a bus failure, a
  /// conversion not done after kMaxPolls ticks) after which the next step starts afresh.
  Result<std::optional<std::int16_t>> step(unsigned channel, double now_s);

 private:
  using Step = Result<std::optional<std::int16_t>>;

  Step begin(unsigned channel, double now_s);
  Step lose(Error why) {
    in_flight_.reset();
    return why;
  }
  /// The channel after `channel` in turn, the same one when it is alone.
  [[nodiscard]] unsigned next_after(unsigned channel) const;

  std::unique_ptr<linux_os::I2cBus> bus_;
  linux_os::Ads1115Reader adc_;
  std::vector<unsigned> channels_;
  std::optional<unsigned> in_flight_;  ///< the channel being converted
  double started_s_ = 0.0;             ///< the tick that started it
  unsigned polls_ = 0;                 ///< its polls so far
};

Ads1115Chip::Step Ads1115Chip::step(unsigned channel, double now_s) {
  if (!in_flight_) return begin(channel, now_s);
  // Another axis's conversion, or one started by this tick's other axis: not this poll's.
  if (*in_flight_ != channel || now_s <= started_s_) return std::optional<std::int16_t>{};
  auto done = adc_.poll();
  if (!done) return lose(done.error());
  if (!done.value()) {
    if (++polls_ < kMaxPolls) return std::optional<std::int16_t>{};
    return lose(
        adc_.error(channel, "conversion not done after " + std::to_string(kMaxPolls) + " ticks"));
  }
  auto code = adc_.fetch();
  if (!code) return lose(code.error());
  // A start that fails spoils only the next reading: the next step starts again and reports
  // the failure if the bus still fails.
  (void)begin(next_after(channel), now_s);
  return std::optional<std::int16_t>{code.value()};
}

Ads1115Chip::Step Ads1115Chip::begin(unsigned channel, double now_s) {
  if (auto r = adc_.start(channel); !r) return lose(r.error());
  in_flight_ = channel;
  started_s_ = now_s;
  polls_ = 0;
  return std::optional<std::int16_t>{};
}

unsigned Ads1115Chip::next_after(unsigned channel) const {
  const auto it = std::find(channels_.begin(), channels_.end(), channel);
  if (it == channels_.end() || it + 1 == channels_.end()) return channels_.front();
  return *(it + 1);
}

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

Result<SensorReading> pot_angle(const control::PotReading& r, const std::string& what) {
  if (r.ok()) return SensorReading{r.deg};
  return fail(what + ": " + std::string(control::to_string(r.status)));
}

class Mcp3008Sensor final : public AxisSensor {
 public:
  Mcp3008Sensor(std::unique_ptr<linux_os::SpiBus> bus, unsigned channel,
                const control::PotInputConfig& pot, std::string what)
      : bus_(std::move(bus)), adc_(*bus_), channel_(channel), pot_(pot), what_(std::move(what)) {}
  /// One SPI transfer: the MCP3008 converts while it clocks the result out, nothing to wait for.
  Result<SensorReading> read(double /*now_s*/) override {
    auto code = adc_.read(channel_);
    if (!code) {
      pot_.reset();
      return code.error();
    }
    return pot_angle(pot_.push(code.value()), what_);
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  std::unique_ptr<linux_os::SpiBus> bus_;
  linux_os::Mcp3008Reader adc_;
  unsigned channel_;
  control::PotInput pot_;
  std::string what_;
};

class Ads1115Sensor final : public AxisSensor {
 public:
  Ads1115Sensor(std::shared_ptr<Ads1115Chip> chip, const HardwareAxisConfig& a, std::string what)
      : chip_(std::move(chip)), channel_(a.adc_channel), pot_(a.pot), what_(std::move(what)) {}
  Result<SensorReading> read(double now_s) override {
    auto code = chip_->step(channel_, now_s);
    if (!code) {
      pot_.reset();
      return code.error();
    }
    if (!code.value()) return SensorReading{};
    return pot_angle(pot_.push(*code.value()), what_);
  }
  [[nodiscard]] std::string describe() const override { return what_; }

 private:
  std::shared_ptr<Ads1115Chip> chip_;
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

/// The ADS1115 of `a`, opened now or shared with the other axis, with `a`'s channel added.
std::shared_ptr<Ads1115Chip> ads1115_chip(const HardwareAxisConfig& a, HardwarePorts& ports) {
  std::shared_ptr<Ads1115Chip>& chip = ports.ads1115_chips[{a.adc_device, a.adc_address}];
  if (!chip) {
    auto bus = ports.open_i2c(a.adc_device);
    if (!bus) throw UsageError(a.key("adc_device") + ": " + bus.error().message);
    chip = std::make_shared<Ads1115Chip>(std::move(bus).value(), a.adc_address);
  } else if (chip->has_channel(a.adc_channel)) {
    throw UsageError(a.key("adc_channel") + ": the other axis reads channel " +
                     std::to_string(a.adc_channel) + " of this ADS1115 already");
  }
  chip->add_channel(a.adc_channel);
  return chip;
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
  return p;
}

std::unique_ptr<AxisActuator> make_actuator(const HardwareAxisConfig& a, const PwmConfig& pwm,
                                            HardwarePorts& ports) {
  if (a.drive == AxisDriveKind::Relay) {
    const bool pp = a.relay_power.has_value();
    auto first = output_line(ports, pp ? *a.relay_power : *a.relay_forward);
    auto second = output_line(ports, pp ? *a.relay_polarity : *a.relay_reverse);
    return std::make_unique<RelayActuator>(
        std::move(first), std::move(second), pp,
        control::PowerPolarityConfig{a.relay.reversal_dead_s, a.polarity_settle_s},
        pp ? "relays (power + polarity)" : "relays (forward/reverse)");
  }
  if (a.drive == AxisDriveKind::Pot) {
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
  const std::string what = a.name + " pot (" + std::string(name_of(kAxisSensorKinds, a.sensor)) +
                           " " + a.adc_device + " channel " + std::to_string(a.adc_channel) + ")";
  if (a.sensor == AxisSensorKind::Mcp3008) {
    auto bus = ports.open_spi(a.adc_device, 1'000'000);
    if (!bus) throw UsageError(a.key("adc_device") + ": " + bus.error().message);
    return std::make_unique<Mcp3008Sensor>(std::move(bus).value(), a.adc_channel, a.pot, what);
  }
  return std::make_unique<Ads1115Sensor>(ads1115_chip(a, ports), a, what);
}

}  // namespace azt::app
