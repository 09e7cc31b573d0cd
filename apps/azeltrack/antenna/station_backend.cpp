#include "antenna/station_backend.hpp"

#include <algorithm>
#include <optional>
#include <utility>

namespace azt::app {
namespace {

constexpr std::array<const char*, 2> kAxisNames{"az", "el"};

/// The sky position with the mount angle and motion, or nullopt while a reading is stale or an
/// axis is faulted (no cached angle is ever reported).
std::optional<proto::PositionReport> station_position(const control::StationController& station,
                                                      double now_s) {
  const auto sky = station.sky_position(now_s);
  if (!sky) return std::nullopt;
  const auto az = station.az();
  const auto el = station.el();
  return proto::PositionReport{sky->az_deg, sky->el_deg, az.mount_deg, az.moving || el.moving,
                               station.faulted()};
}

/// "az: stall: driven for 2 s …", one line per latched axis fault.
std::vector<std::string> station_faults(const control::StationController& station) {
  std::vector<std::string> out;
  for (const auto& [name, axis] : {std::pair{"az", station.az()}, {"el", station.el()}}) {
    if (axis.fault != control::FaultKind::None) {
      out.push_back(std::string(name) + ": " + std::string(control::to_string(axis.fault)) + ": " +
                    axis.reason);
    }
  }
  return out;
}

class StationBackend final : public AntennaBackend {
 public:
  StationBackend(const control::StationControlConfig& control, control::AzEl start_mount,
                 const control::PositionCorrections& corrections, ports::StationPorts ports,
                 std::string describe)
      : ports_(std::move(ports)), station_(control, start_mount), describe_(std::move(describe)) {
    station_.set_corrections(corrections);
  }
  ~StationBackend() override { stop_now(0.0); }
  StationBackend(const StationBackend&) = delete;
  StationBackend& operator=(const StationBackend&) = delete;
  StationBackend(StationBackend&&) = delete;
  StationBackend& operator=(StationBackend&&) = delete;

  void tick(double now_s, const control::Demand& demand, const control::AzEl& rate) override {
    if (const auto held = latched_sensor()) {
      // Never drive on angles read at the wrong resolution: stopped, and saying why.
      stop_with(now_s, "held by the sensor fault (" + *held + ")");
      return;
    }
    read_sensors(now_s);
    // Both axes' readings go in together, stamped with the older: if either sensor falls silent
    // the station sees a stale position and stops the drives.
    if (fresh_[0] && fresh_[1]) {
      station_.on_encoder_reading(std::min(fresh_[0]->at_s, fresh_[1]->at_s), fresh_[0]->deg,
                                  fresh_[1]->deg);
      fresh_ = {};
    }
    apply(now_s, station_.tick(now_s, demand, rate));
  }

  void set_limits(double now_s, const control::LimitSwitches& limits) override {
    apply(now_s, station_.set_limits(limits));
  }

  [[nodiscard]] std::optional<proto::PositionReport> position(double now_s) const override {
    return station_position(station_, now_s);
  }

  void stop_now(double now_s) override { stop_with(now_s, "stopped by the daemon"); }

  /// Both drives off now, the station latched with `reason` until the faults are cleared.
  void stop_with(double now_s, std::string_view reason) {
    station_.emergency_stop(now_s, reason);
    const control::Duties d = station_.duties();
    const std::array<std::optional<double>, 2> setpoint{d.az_setpoint_deg, d.el_setpoint_deg};
    for (std::size_t i = 0; i < 2; ++i) {
      (void)ports_.drives.at(i)->apply(now_s, 0.0, setpoint.at(i));
      ports_.drives.at(i)->off(now_s);
    }
  }

  [[nodiscard]] std::vector<std::string> faults() const override {
    std::vector<std::string> out = station_faults(station_);
    if (!drive_fault_.empty()) out.push_back(drive_fault_);
    for (std::size_t i = 0; i < 2; ++i) {
      for (const auto& f : {ports_.sensors.at(i)->latched_fault(), sensor_fault_.at(i)}) {
        // Two axes on one link (a hub) report its loss once.
        if (f && std::find(out.begin(), out.end(), *f) == out.end()) out.push_back(*f);
      }
    }
    return out;
  }

  void clear_faults() override {
    station_.clear_faults();
    drive_fault_.clear();
    for (const auto& sensor : ports_.sensors) sensor->clear_fault();
  }

  void set_corrections(const control::PositionCorrections& corrections) override {
    station_.set_corrections(corrections);
  }

  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override {
    return station_.encoder_reading();
  }

  [[nodiscard]] std::string describe() const override { return describe_; }

 private:
  /// The first latched sensor fault, if any.
  [[nodiscard]] std::optional<std::string> latched_sensor() const {
    for (const auto& sensor : ports_.sensors) {
      if (auto fault = sensor->latched_fault()) return fault;
    }
    return std::nullopt;
  }

  void read_sensors(double now_s) {
    for (std::size_t i = 0; i < 2; ++i) {
      auto r = ports_.sensors.at(i)->read(now_s);
      if (!r) {
        sensor_fault_.at(i) = r.error().message;  // no reading: the station goes stale
      } else if (r.value()) {
        fresh_.at(i) = r.value();
        sensor_fault_.at(i).reset();
      }
      // Otherwise nothing new yet (an ADC conversion running, a hub between frames).
    }
  }

  void apply(double now_s, const control::Duties& d) {
    const std::array<double, 2> duty{d.az, d.el};
    const std::array<std::optional<double>, 2> setpoint{d.az_setpoint_deg, d.el_setpoint_deg};
    for (std::size_t i = 0; i < 2; ++i) {
      if (auto r = ports_.drives.at(i)->apply(now_s, duty.at(i), setpoint.at(i)); !r) {
        drive_fault_ = std::string(kAxisNames.at(i)) + " drive: " + r.error().message;
        stop_now(now_s);
        return;
      }
    }
  }

  ports::StationPorts ports_;
  control::StationController station_;
  std::array<ports::SensorReading, 2> fresh_;
  std::array<std::optional<std::string>, 2> sensor_fault_;
  std::string drive_fault_;
  std::string describe_;
};

}  // namespace

std::unique_ptr<AntennaBackend> make_station_backend(
    const control::StationControlConfig& control, control::AzEl start_mount,
    const control::PositionCorrections& corrections, ports::StationPorts ports,
    std::string describe) {
  return std::make_unique<StationBackend>(control, start_mount, corrections, std::move(ports),
                                          std::move(describe));
}

}  // namespace azt::app
