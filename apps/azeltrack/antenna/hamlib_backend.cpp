// The `hamlib` backend: an existing rotator controller (GS-232, SPID, EasyComm boxes, or another
// rotctld) closes its own loop; azeltrack sends it setpoints and reads its position back.
#include <chrono>
#include <cmath>

#include "antenna/antenna_backend.hpp"
#include "azt/control/axis_geometry.hpp"
#include "azt/linux/hamlib_rotator.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

class HamlibBackend final : public AntennaBackend {
 public:
  HamlibBackend(std::unique_ptr<linux_os::HamlibRotator> rotator, const DaemonConfig& config)
      : rotator_(std::move(rotator)),
        config_(config.hamlib),
        az_range_(config.sim.setup.station.az_range),
        el_range_(config.sim.setup.station.el_range),
        stale_s_(std::max(1.0, 5.0 * config.hamlib.poll_s)) {}

  void tick(double /*now_s*/, const control::Demand& demand,
            const control::AzEl& /*rate*/) override {
    if (demand.position) {
      // Hamlib rotators take azimuth in their own convention; 0..360 is what every backend
      // accepts, and the box chooses its path.
      rotator_->command_position(control::wrap_360(demand.position->az_deg),
                                 demand.position->el_deg);
      holding_ = false;
    } else if (demand.jog) {
      const auto here = position_now();
      if (!here) return;
      const double az = demand.jog->az == 0
                            ? here->az_deg
                            : control::wrap_360(here->az_deg + 170.0 * demand.jog->az);
      const double el = demand.jog->el == 0
                            ? here->el_deg
                            : (demand.jog->el > 0 ? el_range_.max_deg : el_range_.min_deg);
      rotator_->command_position(az, el);
      holding_ = false;
    } else if (!holding_) {
      rotator_->command_stop();
      holding_ = true;
    }
  }

  [[nodiscard]] std::optional<proto::PositionReport> position(double /*now_s*/) const override {
    return position_now();
  }

  void stop_now(double /*now_s*/) override {
    rotator_->command_stop();
    holding_ = true;
  }

  [[nodiscard]] std::vector<std::string> faults() const override {
    if (rotator_->connected()) return {};
    return {"hamlib: rotator not connected: " + rotator_->last_error()};
  }

  void clear_faults() override {}

  bool set_corrections(const control::PositionCorrections& /*corrections*/) override {
    return false;
  }

  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override {
    return std::nullopt;
  }

  [[nodiscard]] std::string describe() const override {
    return "Hamlib rotator model " + std::to_string(config_.model) +
           (config_.device.empty() ? std::string() : " on " + config_.device);
  }

 private:
  [[nodiscard]] std::optional<proto::PositionReport> position_now() const {
    const auto r = rotator_->latest();
    if (!r || !rotator_->connected()) return std::nullopt;
    const double age =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - r->at).count();
    if (age > stale_s_) return std::nullopt;
    return proto::PositionReport{control::wrap_360(r->az_deg), r->el_deg, r->az_deg, false, false};
  }

  std::unique_ptr<linux_os::HamlibRotator> rotator_;
  linux_os::HamlibConfig config_;
  control::AzimuthRange az_range_;
  control::ElevationRange el_range_;
  double stale_s_;
  bool holding_ = false;
};

}  // namespace

std::unique_ptr<AntennaBackend> make_hamlib_backend(const DaemonConfig& config) {
  auto rotator = linux_os::HamlibRotator::open(config.hamlib);
  if (!rotator) throw UsageError("[hamlib]: " + rotator.error().message);
  return std::make_unique<HamlibBackend>(std::move(rotator).value(), config);
}

}  // namespace azt::app
