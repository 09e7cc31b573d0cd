#include "azt/avr/firmware_station_ports.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "azt/avr/avr_hub.hpp"
#include "azt/proto/hub_frame.hpp"

namespace azt::avr {
namespace {

constexpr double kStepS = 0.005;
constexpr std::array<const char*, 2> kAxisNames{"az", "el"};

HubAxisSetup encoder_for(const sim::AxisParams& axis) {
  if (axis.encoder_bits == 12) return {EncoderModelKind::As5045, 12};
  return {EncoderModelKind::SsiBinary, axis.encoder_bits};
}

/// What both axes' ports share: the plants, the AVR running the firmware, and its last frame.
class FirmwareRig {
 public:
  FirmwareRig(const sim::PlantSetup& p, std::unique_ptr<AvrHub> hub)
      : faults_(p.faults),
        antenna_(p.az, p.el, proto::HubFrameVersion::Crc8, sim::LinkFaults{}, p.seed),
        hub_(std::move(hub)) {
    hub_->on_byte = [this](std::uint8_t byte, double at_us) {
      proto::HubFrame f{};
      if (decoder_.push(byte, f) == proto::HubFrameStatus::Ok) {
        frame_ = f.reading;
        frame_at_us_ = at_us;
      }
    };
  }

  void set_duty(std::size_t axis, double duty) { duty_.at(axis) = duty; }
  void set_encoder_fault(bool azimuth, EncoderFault fault) { hub_->set_fault(azimuth, fault); }

  /// The newest frame by `now_s`, and when it arrived on the caller's clock.
  std::optional<std::pair<proto::HubReading, double>> frame_at(double now_s) {
    if (!last_s_ || *last_s_ != now_s) advance(now_s);
    if (!frame_) return std::nullopt;
    return std::make_pair(*frame_, now_s - (hub_->now_us() - frame_at_us_) / 1e6);
  }

  /// Each frame is reported once per axis.
  bool take(std::size_t axis) { return std::exchange(fresh_.at(axis), false); }

  [[nodiscard]] std::string describe() const {
    return "simulated antenna read by the EncoderHub firmware on a simulated ATmega328P";
  }

 private:
  void advance(double now_s) {
    if (!first_s_) first_s_ = now_s;
    const double dt = last_s_ ? std::clamp(now_s - *last_s_, 0.0, 1.0) : 0.0;
    last_s_ = now_s;
    const double before_us = frame_at_us_;
    const auto steps = static_cast<int>(std::ceil(dt / kStepS));
    for (int i = 0; i < steps; ++i) {
      const double step = std::min(kStepS, dt - i * kStepS);
      antenna_.step(duty_[0], duty_[1], step, 1);
      faults_.inject_due(now_s - *first_s_, antenna_);
      hub_->set_counts(antenna_.az().encoder_raw(), antenna_.el().encoder_raw());
      hub_->run_for(step);
    }
    if (frame_at_us_ != before_us) fresh_ = {true, true};
  }

  sim::FaultSchedule faults_;
  sim::SimAntenna antenna_;
  std::unique_ptr<AvrHub> hub_;
  proto::HubDecoder decoder_{proto::HubAccept::Crc8Only, proto::HubSync::AwaitDelimiter};
  std::array<double, 2> duty_{};
  std::optional<double> first_s_;
  std::optional<double> last_s_;
  std::optional<proto::HubReading> frame_;
  double frame_at_us_ = -1.0;
  std::array<bool, 2> fresh_{};
};

class RigDrive final : public ports::AxisDrive {
 public:
  RigDrive(std::shared_ptr<FirmwareRig> rig, std::size_t axis)
      : rig_(std::move(rig)), axis_(axis) {}
  Result<bool> apply(double /*now_s*/, double duty, std::optional<double> /*setpoint*/) override {
    rig_->set_duty(axis_, duty);
    return true;
  }
  void off(double /*now_s*/) override { rig_->set_duty(axis_, 0.0); }
  [[nodiscard]] std::string describe() const override { return rig_->describe(); }

 private:
  std::shared_ptr<FirmwareRig> rig_;
  std::size_t axis_;
};

class RigSensor final : public ports::AxisSensor {
 public:
  RigSensor(std::shared_ptr<FirmwareRig> rig, std::size_t axis)
      : rig_(std::move(rig)), axis_(axis) {}
  Result<ports::SensorReading> read(double now_s) override {
    const auto frame = rig_->frame_at(now_s);
    if (!frame || !rig_->take(axis_)) return ports::SensorReading{};
    const proto::HubReading& r = frame->first;
    const auto error = axis_ == 0 ? r.az_error : r.el_error;
    if (error != proto::HubAxisError::None) {
      return fail(std::string(kAxisNames.at(axis_)) +
                  " encoder (EncoderHub): " + proto::hub_axis_error_name(error));
    }
    const double deg = axis_ == 0 ? proto::hub_raw_to_deg(r.az_raw, r.az_bits)
                                  : proto::hub_raw_to_deg(r.el_raw, r.el_bits);
    return ports::SensorReading{ports::AxisSample{deg, frame->second}};
  }
  [[nodiscard]] std::string describe() const override { return rig_->describe(); }

 private:
  std::shared_ptr<FirmwareRig> rig_;
  std::size_t axis_;
};

}  // namespace

Result<FirmwareStation> make_firmware_station(const sim::PlantSetup& plant,
                                              const std::string& elf_path) {
  AvrHubSetup setup;
  setup.elf_path = elf_path;
  setup.az = encoder_for(plant.az);
  setup.el = encoder_for(plant.el);
  auto hub = AvrHub::load(setup);
  if (!hub) return hub.error();
  auto rig = std::make_shared<FirmwareRig>(plant, std::move(hub).value());
  FirmwareStation station;
  for (std::size_t i = 0; i < 2; ++i) {
    station.ports.drives.at(i) = std::make_unique<RigDrive>(rig, i);
    station.ports.sensors.at(i) = std::make_unique<RigSensor>(rig, i);
  }
  station.set_encoder_fault = [rig](bool azimuth, EncoderFault fault) {
    rig->set_encoder_fault(azimuth, fault);
  };
  return station;
}

}  // namespace azt::avr
