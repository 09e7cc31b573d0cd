#include "azt/sim/sim_station_ports.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

namespace azt::sim {
namespace {

/// What the two axes' ports share: the plants, the link and the schedule of faults.
class SimRig {
 public:
  explicit SimRig(const PlantSetup& p)
      : faults_(p.faults), antenna_(p.az, p.el, p.frame_version, p.link, p.seed) {}

  void set_duty(std::size_t axis, double duty) { (axis == 0 ? az_duty_ : el_duty_) = duty; }

  /// The hub's frame at `now_s`, if the link delivered one: the plants are run up to `now_s`
  /// first, once per instant.
  const std::optional<control::AzEl>& frame_at(double now_s) {
    if (frame_s_ && *frame_s_ == now_s) return frame_;
    if (frame_s_) {
      // Capped after a suspend: a second of simulated motion at most per tick.
      const double dt = std::clamp(now_s - *frame_s_, 0.0, 1.0);
      const int substeps = std::max(1, static_cast<int>(std::ceil(dt / 0.01)));
      if (dt > 0.0) antenna_.step(az_duty_, el_duty_, dt, substeps);
    }
    if (!first_s_) first_s_ = now_s;  // the configured faults are timed from the first tick
    frame_s_ = now_s;
    faults_.inject_due(now_s - *first_s_, antenna_);
    frame_ = antenna_.transmit_frame();
    return frame_;
  }

  [[nodiscard]] std::string describe() const {
    return "simulated antenna (" + std::to_string(antenna_.az().encoder_bits()) + "/" +
           std::to_string(antenna_.el().encoder_bits()) + "-bit encoders)";
  }

 private:
  FaultSchedule faults_;  ///< [sim.az] / [sim.el] fault
  SimAntenna antenna_;
  double az_duty_ = 0.0;
  double el_duty_ = 0.0;
  std::optional<double> first_s_;
  std::optional<double> frame_s_;
  std::optional<control::AzEl> frame_;
};

class SimDrive final : public ports::AxisDrive {
 public:
  SimDrive(std::shared_ptr<SimRig> rig, std::size_t axis) : rig_(std::move(rig)), axis_(axis) {}
  Result<bool> apply(double /*now_s*/, double duty, std::optional<double> /*setpoint*/) override {
    rig_->set_duty(axis_, duty);
    return true;
  }
  void off(double /*now_s*/) override { rig_->set_duty(axis_, 0.0); }
  [[nodiscard]] std::string describe() const override { return rig_->describe(); }

 private:
  std::shared_ptr<SimRig> rig_;
  std::size_t axis_;
};

class SimSensor final : public ports::AxisSensor {
 public:
  SimSensor(std::shared_ptr<SimRig> rig, std::size_t axis) : rig_(std::move(rig)), axis_(axis) {}
  Result<ports::SensorReading> read(double now_s) override {
    const auto& frame = rig_->frame_at(now_s);
    if (!frame) return ports::SensorReading{};  // a frame lost on the link: nothing new
    return ports::SensorReading{
        ports::AxisSample{axis_ == 0 ? frame->az_deg : frame->el_deg, now_s}};
  }
  [[nodiscard]] std::string describe() const override { return rig_->describe(); }

 private:
  std::shared_ptr<SimRig> rig_;
  std::size_t axis_;
};

}  // namespace

ports::StationPorts make_sim_station_ports(const PlantSetup& plant) {
  auto rig = std::make_shared<SimRig>(plant);
  ports::StationPorts p;
  for (std::size_t i = 0; i < 2; ++i) {
    p.drives.at(i) = std::make_unique<SimDrive>(rig, i);
    p.sensors.at(i) = std::make_unique<SimSensor>(rig, i);
  }
  return p;
}

}  // namespace azt::sim
