// The `pwm` backend: real encoders through the EncoderHub on a serial device, real motors through
// two IBT-2 H-bridges on sysfs PWM, driven by the same StationController as the simulation.
// The mount's rates and encoder resolutions are those of the [sim.az] / [sim.el] tables (the
// simulated antenna is the model of this one), the travel is [geometry].
#include <algorithm>
#include <chrono>

#include "antenna_backend.hpp"
#include "azt/control/station_controller.hpp"
#include "azt/linux/hub_serial_link.hpp"
#include "azt/linux/pwm_hbridge.hpp"
#include "azt/sim/station_sim.hpp"
#include "cli_error.hpp"
#include "station_reports.hpp"

namespace azt::app {
namespace {

linux_os::PwmHBridge open_bridge(const PwmConfig& p, unsigned r, unsigned l, const char* axis) {
  linux_os::PwmHBridgeConfig c;
  c.chip_dir = p.chip_dir;
  c.rpwm_channel = r;
  c.lpwm_channel = l;
  c.frequency_hz = p.frequency_hz;
  c.dead_time_s = p.dead_time_s;
  auto bridge = linux_os::PwmHBridge::open(c);
  if (!bridge) throw UsageError(std::string("[pwm] ") + axis + ": " + bridge.error().message);
  return std::move(bridge).value();
}

class PwmBackend final : public AntennaBackend {
 public:
  PwmBackend(boost::asio::io_context& io, const DaemonConfig& config)
      : station_(sim::station_control_config(config.sim.setup),
                 control::AzEl{config.sim.setup.az_plant.start_deg,
                               config.sim.setup.el_plant.start_deg}),
        az_(open_bridge(config.pwm, config.pwm.az_rpwm, config.pwm.az_lpwm, "azimuth")),
        el_(open_bridge(config.pwm, config.pwm.el_rpwm, config.pwm.el_lpwm, "elevation")),
        hub_device_(config.hub.device) {
    station_.set_corrections(config.sim.setup.corrections);
    auto hub = linux_os::HubSerialLink::open(
        io, config.hub,
        [this](const proto::HubFrame& f) {
          latest_ = control::AzEl{proto::hub_raw_to_deg(f.reading.az_raw, f.reading.az_bits),
                                  proto::hub_raw_to_deg(f.reading.el_raw, f.reading.el_bits)};
          latest_at_ = std::chrono::steady_clock::now();
        },
        [this](const std::string& event) { hub_event_ = event; });
    if (!hub) {
      (void)az_.disable(0.0);
      (void)el_.disable(0.0);
      throw UsageError("[hub] device: " + hub.error().message);
    }
    hub_ = std::move(hub).value();
  }

  void tick(double now_s, const control::Demand& demand, const control::AzEl& rate) override {
    if (latest_) {
      // Stamped with when the frame arrived, not with this tick: staleness counts from the frame.
      const double age_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - latest_at_).count();
      station_.on_encoder_reading(now_s - std::max(0.0, age_s), latest_->az_deg, latest_->el_deg);
      latest_.reset();
    }
    apply(now_s, station_.tick(now_s, demand, rate));
  }

  void set_limits(double now_s, const control::LimitSwitches& limits) override {
    apply(now_s, station_.set_limits(limits));
  }

  [[nodiscard]] std::optional<proto::PositionReport> position(double now_s) const override {
    return station_position(station_, now_s);
  }

  void stop_now(double now_s) override {
    station_.emergency_stop(now_s);
    (void)az_.disable(now_s);
    (void)el_.disable(now_s);
  }

  [[nodiscard]] std::vector<std::string> faults() const override {
    std::vector<std::string> out = station_faults(station_);
    if (!drive_fault_.empty()) out.push_back(drive_fault_);
    if (!hub_->connected()) out.push_back("hub: " + hub_event_);
    return out;
  }

  void clear_faults() override {
    station_.clear_faults();
    drive_fault_.clear();
  }

  bool set_corrections(const control::PositionCorrections& corrections) override {
    station_.set_corrections(corrections);
    return true;
  }

  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override {
    return station_.encoder_reading();
  }

  [[nodiscard]] std::string describe() const override {
    return "EncoderHub on " + hub_device_ + ", IBT-2 bridges on sysfs PWM";
  }

 private:
  void apply(double now_s, const control::Duties& d) {
    for (auto [bridge, duty, name] : {std::tuple{&az_, d.az, "az"}, std::tuple{&el_, d.el, "el"}}) {
      if (auto r = bridge->apply(now_s, duty); !r) {
        drive_fault_ = std::string(name) + " drive: " + r.error().message;
        stop_now(now_s);
      }
    }
  }

  control::StationController station_;
  linux_os::PwmHBridge az_;
  linux_os::PwmHBridge el_;
  std::unique_ptr<linux_os::HubSerialLink> hub_;
  std::optional<control::AzEl> latest_;
  std::chrono::steady_clock::time_point latest_at_;
  std::string hub_event_;
  std::string drive_fault_;
  std::string hub_device_;
};

}  // namespace

std::unique_ptr<AntennaBackend> make_pwm_backend(boost::asio::io_context& io,
                                                 const DaemonConfig& config) {
  return std::make_unique<PwmBackend>(io, config);
}

}  // namespace azt::app
