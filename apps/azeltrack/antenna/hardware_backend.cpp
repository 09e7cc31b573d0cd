// The `hardware` backend (and `pwm`, its both-axes-on-IBT-2-and-EncoderHub form): each axis has
// its own drive and sensor (axis_io.hpp), read and driven by the same StationController as the
// simulation. The mount's rates and encoder resolutions are [mount.az] / [mount.el], the travel
// is [geometry]. The EncoderHub reports its jumpers' bits in every frame: a frame whose bits are
// not the mount's is never used, and latches a fault naming both.
#include <algorithm>
#include <chrono>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_io.hpp"
#include "antenna/controller_reports.hpp"
#include "azt/control/station_controller.hpp"
#include "azt/control/station_setup.hpp"
#include "azt/linux/hub_serial_link.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

control::AxisDriveConfig drive_config(const HardwareAxisConfig& a) {
  control::AxisDriveConfig d;
  if (a.drive == AxisDriveKind::Relay) {
    d.kind = control::DriveKind::Relay;
    d.relay = a.relay;
  } else if (a.drive == AxisDriveKind::Pot) {
    d.kind = control::DriveKind::Setpoint;
    d.setpoint_band_deg = a.setpoint_band_deg;
  }
  return d;
}

control::StationControlConfig control_config(const DaemonConfig& config) {
  control::StationControlConfig c = config.sim.setup.station.control_config();
  c.az_drive = drive_config(config.hardware.az);
  c.el_drive = drive_config(config.hardware.el);
  c.az_absolute = config.hardware.az.sensor != AxisSensorKind::Hub;
  return c;
}

/// One axis's latest reading and when it was taken (the control loop's clock).
struct Sample {
  double deg = 0.0;
  double at_s = 0.0;
};

class HardwareBackend final : public AntennaBackend {
 public:
  HardwareBackend(boost::asio::io_context& io, const DaemonConfig& config, HardwarePorts ports)
      : ports_(std::move(ports)),
        station_(control_config(config), control::AzEl{config.sim.setup.az_plant.start_deg,
                                                       config.sim.setup.el_plant.start_deg}),
        hub_device_(config.hub.device) {
    station_.set_corrections(config.sim.setup.station.corrections);
    // Sensors first, then drives: a drive is only ever opened once everything it needs exists.
    for (const HardwareAxisConfig* a : {&config.hardware.az, &config.hardware.el}) {
      if (a->sensor != AxisSensorKind::Hub) sensors_.at(index(*a)) = make_adc_sensor(*a, ports_);
    }
    if (config.hardware.uses_hub()) open_hub(io, config);
    for (const HardwareAxisConfig* a : {&config.hardware.az, &config.hardware.el}) {
      try {
        drives_.at(index(*a)) = make_actuator(*a, config.pwm, ports_);
      } catch (const UsageError&) {
        stop_now(0.0);
        throw;
      }
    }
    describe_ = "az: " + drives_[0]->describe() + ", " + sensor_name(config.hardware.az) +
                "; el: " + drives_[1]->describe() + ", " + sensor_name(config.hardware.el);
  }

  void tick(double now_s, const control::Demand& demand, const control::AzEl& rate) override {
    if (!bits_fault_[0].empty() || !bits_fault_[1].empty()) {
      stop_now(now_s);  // never drive on angles read at the wrong resolution
      return;
    }
    read_sensors(now_s);
    // Both axes' readings go in together, stamped with the older: if either sensor falls silent
    // the station sees a stale position and stops the drives.
    if (fresh_[0] && fresh_[1]) {
      station_.on_encoder_reading(std::min(fresh_[0]->at_s, fresh_[1]->at_s), fresh_[0]->deg,
                                  fresh_[1]->deg);
      fresh_[0].reset();
      fresh_[1].reset();
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
    const control::Duties d = station_.duties();
    for (std::size_t i = 0; i < drives_.size(); ++i) {
      if (!drives_.at(i)) continue;
      (void)drives_.at(i)->apply(now_s, 0.0, i == 0 ? d.az_setpoint_deg : d.el_setpoint_deg);
      drives_.at(i)->off(now_s);
    }
  }

  [[nodiscard]] std::vector<std::string> faults() const override {
    std::vector<std::string> out = station_faults(station_);
    if (!drive_fault_.empty()) out.push_back(drive_fault_);
    for (const auto& f : sensor_fault_) {
      if (!f.empty()) out.push_back(f);
    }
    for (const auto& f : bits_fault_) {
      if (!f.empty()) out.push_back(f);
    }
    if (hub_ && !hub_->connected()) out.push_back("hub: " + hub_event_);
    return out;
  }

  void clear_faults() override {
    station_.clear_faults();
    drive_fault_.clear();
    bits_fault_ = {};  // the next disagreeing frame latches it again
  }

  bool set_corrections(const control::PositionCorrections& corrections) override {
    station_.set_corrections(corrections);
    return true;
  }

  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override {
    return station_.encoder_reading();
  }

  [[nodiscard]] std::string describe() const override { return describe_; }

 private:
  static std::size_t index(const HardwareAxisConfig& a) { return a.name == "az" ? 0 : 1; }

  std::string sensor_name(const HardwareAxisConfig& a) const {
    if (a.sensor == AxisSensorKind::Hub) return "EncoderHub on " + hub_device_;
    return sensors_.at(index(a))->describe();
  }

  void open_hub(boost::asio::io_context& io, const DaemonConfig& config) {
    const bool az = config.hardware.az.sensor == AxisSensorKind::Hub;
    const bool el = config.hardware.el.sensor == AxisSensorKind::Hub;
    mount_bits_ = {config.sim.mount.az.encoder_bits, config.sim.mount.el.encoder_bits};
    auto hub = linux_os::HubSerialLink::open(
        io, config.hub,
        [this, az, el](const proto::HubFrame& f) {
          // Stamped with when the frame arrived, not with the next tick: staleness counts from
          // the frame.
          const double at = hub_clock_s();
          if (az && bits_agree(0, f.reading.az_bits))
            fresh_[0] = Sample{proto::hub_raw_to_deg(f.reading.az_raw, f.reading.az_bits), at};
          if (el && bits_agree(1, f.reading.el_bits))
            fresh_[1] = Sample{proto::hub_raw_to_deg(f.reading.el_raw, f.reading.el_bits), at};
        },
        [this](const std::string& event) { hub_event_ = event; });
    if (!hub) throw UsageError("[hub] device: " + hub.error().message);
    hub_ = std::move(hub).value();
  }

  /// Whether a frame's resolution for axis `i` is the mount's. A disagreement is latched (the
  /// readings stop, so the supervisor stops the motors) until the operator clears it: a hub
  /// re-jumpered, or the wrong [mount] encoder_bits, would put every angle and the 1-LSB
  /// window off by a power of two.
  bool bits_agree(std::size_t i, std::uint8_t frame_bits) {
    if (frame_bits == mount_bits_.at(i)) return true;
    const char* axis = i == 0 ? "az" : "el";
    bits_fault_.at(i) = std::string(axis) + ": the EncoderHub reports " +
                        std::to_string(frame_bits) + "-bit frames but [mount." + axis +
                        "] encoder_bits = " + std::to_string(mount_bits_.at(i)) +
                        ": set the jumpers or the configuration to agree";
    return false;
  }

  /// The hub's frames arrive between ticks: their time on the tick's clock is the last tick's
  /// plus the wall time since.
  double hub_clock_s() const {
    return last_tick_s_ +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - last_tick_wall_)
               .count();
  }

  void read_sensors(double now_s) {
    last_tick_s_ = now_s;
    last_tick_wall_ = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < sensors_.size(); ++i) {
      if (!sensors_.at(i)) continue;
      auto r = sensors_.at(i)->read(now_s);
      if (!r) {
        sensor_fault_.at(i) = r.error().message;  // no reading: the station goes stale
      } else if (r.value()) {
        fresh_.at(i) = Sample{*r.value(), now_s};
        sensor_fault_.at(i).clear();
      }
      // Otherwise nothing new yet (an ADC conversion still running): as a hub between frames.
    }
  }

  void apply(double now_s, const control::Duties& d) {
    const std::array<double, 2> duty{d.az, d.el};
    const std::array<std::optional<double>, 2> setpoint{d.az_setpoint_deg, d.el_setpoint_deg};
    for (std::size_t i = 0; i < drives_.size(); ++i) {
      if (auto r = drives_.at(i)->apply(now_s, duty.at(i), setpoint.at(i)); !r) {
        drive_fault_ = std::string(i == 0 ? "az" : "el") + " drive: " + r.error().message;
        stop_now(now_s);
      }
    }
  }

  HardwarePorts ports_;
  control::StationController station_;
  std::array<std::unique_ptr<AxisActuator>, 2> drives_;
  std::array<std::unique_ptr<AxisSensor>, 2> sensors_;
  std::array<std::optional<Sample>, 2> fresh_;
  std::array<std::string, 2> sensor_fault_;
  std::array<std::uint8_t, 2> mount_bits_{};  ///< [mount.az|el] encoder_bits
  std::array<std::string, 2> bits_fault_;     ///< a hub frame's bits were not the mount's
  std::unique_ptr<linux_os::HubSerialLink> hub_;
  double last_tick_s_ = 0.0;
  std::chrono::steady_clock::time_point last_tick_wall_ = std::chrono::steady_clock::now();
  std::string hub_event_;
  std::string drive_fault_;
  std::string hub_device_;
  std::string describe_;
};

}  // namespace

std::unique_ptr<AntennaBackend> make_hardware_backend(boost::asio::io_context& io,
                                                      const DaemonConfig& config,
                                                      HardwarePorts ports) {
  return std::make_unique<HardwareBackend>(io, config, std::move(ports));
}

std::unique_ptr<AntennaBackend> make_pwm_backend(boost::asio::io_context& io,
                                                 const DaemonConfig& config) {
  DaemonConfig both_pwm = config;
  both_pwm.hardware = HardwareConfig{};  // IBT-2 bridges and the EncoderHub on both axes
  return make_hardware_backend(io, both_pwm, HardwarePorts{});
}

}  // namespace azt::app
