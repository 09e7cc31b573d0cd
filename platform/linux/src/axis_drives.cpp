#include "azt/linux/axis_drives.hpp"

#include <initializer_list>
#include <utility>

#include "azt/linux/mcp41010.hpp"

namespace azt::linux_os {
namespace {

class PwmBridgeDrive final : public ports::AxisDrive {
 public:
  PwmBridgeDrive(PwmHBridge bridge, std::unique_ptr<GpioOutput> enable, std::string what)
      : bridge_(std::move(bridge)), enable_(std::move(enable)), what_(std::move(what)) {}
  ~PwmBridgeDrive() override { off(0.0); }
  PwmBridgeDrive(const PwmBridgeDrive&) = delete;
  PwmBridgeDrive& operator=(const PwmBridgeDrive&) = delete;
  PwmBridgeDrive(PwmBridgeDrive&&) = delete;
  PwmBridgeDrive& operator=(PwmBridgeDrive&&) = delete;

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
  PwmHBridge bridge_;
  std::unique_ptr<GpioOutput> enable_;
  std::string what_;
};

class RelayLinesDrive final : public ports::AxisDrive {
 public:
  RelayLinesDrive(std::unique_ptr<GpioOutput> a, std::unique_ptr<GpioOutput> b,
                  std::optional<control::PowerPolarityConfig> pp, std::string what)
      : a_(std::move(a)),
        b_(std::move(b)),
        power_polarity_(pp.has_value()),
        relays_(pp.value_or(control::PowerPolarityConfig{})),
        what_(std::move(what)) {}
  ~RelayLinesDrive() override { off(0.0); }
  RelayLinesDrive(const RelayLinesDrive&) = delete;
  RelayLinesDrive& operator=(const RelayLinesDrive&) = delete;
  RelayLinesDrive(RelayLinesDrive&&) = delete;
  RelayLinesDrive& operator=(RelayLinesDrive&&) = delete;

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
  Result<bool> set_all(std::initializer_list<std::pair<GpioOutput*, bool>> lines, double now_s) {
    for (const auto& [line, on] : lines) {
      if (line->active() == on) continue;
      if (auto r = line->set(on); !r) {
        off(now_s);
        return r.error();
      }
    }
    return true;
  }

  std::unique_ptr<GpioOutput> a_;
  std::unique_ptr<GpioOutput> b_;
  bool power_polarity_;
  control::PowerPolarityRelays relays_;
  std::string what_;
};

class Mcp41010Drive final : public ports::AxisDrive {
 public:
  Mcp41010Drive(std::unique_ptr<SpiBus> bus, const control::SetpointCalibration& cal,
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
  std::unique_ptr<SpiBus> bus_;
  Mcp41010Writer pot_;
  control::SetpointDrive drive_;
  std::optional<double> last_setpoint_;
  std::string what_;
};

}  // namespace

std::unique_ptr<ports::AxisDrive> make_pwm_bridge_drive(PwmHBridge bridge,
                                                        std::unique_ptr<GpioOutput> enable,
                                                        std::string what) {
  return std::make_unique<PwmBridgeDrive>(std::move(bridge), std::move(enable), std::move(what));
}

std::unique_ptr<ports::AxisDrive> make_relay_lines_drive(
    std::unique_ptr<GpioOutput> first, std::unique_ptr<GpioOutput> second,
    std::optional<control::PowerPolarityConfig> power_polarity, std::string what) {
  return std::make_unique<RelayLinesDrive>(std::move(first), std::move(second), power_polarity,
                                           std::move(what));
}

std::unique_ptr<ports::AxisDrive> make_mcp41010_drive(std::unique_ptr<SpiBus> bus,
                                                      const control::SetpointCalibration& wiper,
                                                      std::string what) {
  return std::make_unique<Mcp41010Drive>(std::move(bus), wiper, std::move(what));
}

}  // namespace azt::linux_os
