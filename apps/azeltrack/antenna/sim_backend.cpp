// The `sim` backend: the simulated plants and EncoderHub link stepped in real time by the
// daemon's tick, read and driven by the same StationController the simulations measure.
#include <algorithm>
#include <cmath>

#include "antenna/antenna_backend.hpp"
#include "antenna/controller_reports.hpp"
#include "azt/control/station_controller.hpp"
#include "azt/proto/hub_frame.hpp"
#include "azt/sim/sim_antenna.hpp"
#include "azt/sim/station_sim.hpp"

namespace azt::app {
namespace {

class SimBackend final : public AntennaBackend {
 public:
  explicit SimBackend(const sim::StationSimSetup& s)
      : faults_(s.plant_faults),
        antenna_(s.az_plant, s.el_plant, s.frame_version, s.link, s.seed),
        station_(sim::station_control_config(s),
                 control::AzEl{s.az_plant.start_deg, s.el_plant.start_deg}) {
    station_.set_corrections(s.station.corrections);
  }

  void tick(double now_s, const control::Demand& demand, const control::AzEl& rate) override {
    if (last_s_) {
      // The plants run for the real time since the last tick with the duties then applied;
      // a late tick is simulated exactly as long as it was late (capped, after a suspend).
      const double dt = std::clamp(now_s - *last_s_, 0.0, 1.0);
      const int substeps = std::max(1, static_cast<int>(std::ceil(dt / 0.01)));
      if (dt > 0.0) antenna_.step(duties_.az, duties_.el, dt, substeps);
    }
    last_s_ = now_s;
    if (!first_s_) first_s_ = now_s;  // the configured faults are timed from the first tick
    faults_.inject_due(now_s - *first_s_, antenna_);
    if (const auto reading = antenna_.transmit_frame()) {
      station_.on_encoder_reading(now_s, reading->az_deg, reading->el_deg);
    }
    duties_ = station_.tick(now_s, demand, rate);
  }

  [[nodiscard]] std::optional<proto::PositionReport> position(double now_s) const override {
    return station_position(station_, now_s);
  }

  void stop_now(double now_s) override {
    station_.emergency_stop(now_s);
    duties_ = control::Duties{};
  }

  [[nodiscard]] std::vector<std::string> faults() const override {
    return station_faults(station_);
  }

  void clear_faults() override { station_.clear_faults(); }

  bool set_corrections(const control::PositionCorrections& corrections) override {
    station_.set_corrections(corrections);
    return true;
  }

  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override {
    return station_.encoder_reading();
  }

  void set_limits(double /*now_s*/, const control::LimitSwitches& limits) override {
    // The plants run on with these duties until the next tick: a tripped drive stops now.
    duties_ = station_.set_limits(limits);
  }

  [[nodiscard]] std::string describe() const override {
    return "simulated antenna (" + std::to_string(antenna_.az().encoder_bits()) + "/" +
           std::to_string(antenna_.el().encoder_bits()) + "-bit encoders)";
  }

 private:
  sim::FaultSchedule faults_;  ///< [sim.az] / [sim.el] fault
  std::optional<double> first_s_;
  sim::SimAntenna antenna_;
  control::StationController station_;
  control::Duties duties_;
  std::optional<double> last_s_;
};

}  // namespace

std::unique_ptr<AntennaBackend> make_sim_backend(const DaemonConfig& config) {
  return std::make_unique<SimBackend>(config.sim.setup);
}

}  // namespace azt::app
