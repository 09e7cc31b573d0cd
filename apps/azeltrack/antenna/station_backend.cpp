#include "antenna/station_backend.hpp"

#include <optional>
#include <utility>

#include "azt/control/ported_station.hpp"

namespace azt::app {
namespace {

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

/// The daemon's face of the ported station: the same station the virtual-time simulation runs.
class StationBackend final : public AntennaBackend {
 public:
  StationBackend(const control::StationControlConfig& control, control::AzEl start_mount,
                 const control::PositionCorrections& corrections, ports::StationPorts ports,
                 std::string describe)
      : station_(control, start_mount, corrections, std::move(ports)),
        describe_(std::move(describe)) {}

  void tick(double now_s, const control::Demand& demand, const control::AzEl& rate) override {
    station_.tick(now_s, demand, rate, pol_demand_);
  }
  void set_pol_demand(const control::PolDemand& demand) override { pol_demand_ = demand; }
  [[nodiscard]] std::optional<PolStatus> pol_status() const override {
    const control::PolAxis* pol = station_.pol();
    if (pol == nullptr) return std::nullopt;
    const control::AxisStatus s = pol->axis().status();
    return PolStatus{s.mount_deg, pol->target_mount_deg(), s.moving,
                     s.reason,    pol->travel().min_deg,   pol->travel().max_deg};
  }
  void set_pol_limits(double now_s, const control::LimitPair& limits) override {
    station_.set_pol_limits(now_s, limits);
  }
  void set_limits(double now_s, const control::LimitSwitches& limits) override {
    station_.set_limits(now_s, limits);
  }
  [[nodiscard]] std::optional<proto::PositionReport> position(double now_s) const override {
    return station_position(station_.station(), now_s);
  }
  void stop_now(double now_s) override { station_.stop_with(now_s, "stopped by the daemon"); }
  [[nodiscard]] std::vector<std::string> faults() const override { return station_.faults(); }
  void clear_faults() override { station_.clear_faults(); }
  void set_corrections(const control::PositionCorrections& corrections) override {
    station_.set_corrections(corrections);
  }
  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override {
    return station_.station().encoder_reading();
  }
  [[nodiscard]] std::string describe() const override { return describe_; }
  [[nodiscard]] std::vector<NamedAxisStatus> axes() const override {
    const control::StationController& s = station_.station();
    std::vector<NamedAxisStatus> out{{"az", s.az()}};
    if (!s.el_fixed()) out.push_back({"el", s.el()});
    if (const control::PolAxis* pol = station_.pol()) out.push_back({"pol", pol->axis().status()});
    return out;
  }
  std::optional<std::string> home(double now_s, const std::string& axis) override {
    if (axis == "az") return station_.home(now_s, 0);
    if (axis == "el") return station_.home(now_s, 1);
    if (axis == "pol") return station_.home(now_s, 2);
    return "no axis \"" + axis + "\": only az, el and pol can be homed";
  }
  void stop_homing(double now_s, std::string_view reason) override {
    station_.stop_homing(now_s, reason);
  }

 private:
  control::PortedStation station_;
  control::PolDemand pol_demand_;  ///< held until the daemon sets another: none holds the axis
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
