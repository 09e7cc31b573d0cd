#pragma once
// The daemon's own station (control::PortedStation: the controllers and supervisors over the
// ports) on a simulated station's ports, stepped in virtual time, with the plants' truth beside
// it: what every virtual-time simulation (station_sim.hpp, calibration_sim.hpp) runs.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "azt/control/ported_station.hpp"
#include "azt/sim/simulated_station.hpp"
#include "azt/sim/station_sim.hpp"

namespace azt::sim {

/// The daemon's station (PortedStation) over a simulated station's ports, and the plants' truth.
class StationLoop {
 public:
  /// `hub` nullptr: the plain model of setup.plant.
  StationLoop(const StationSimSetup& setup, std::unique_ptr<SimulatedHub> hub);

  /// One control tick at `t_s`: read the hub, drive both axes towards `demand` (nullopt: hold),
  /// and the polarisation axis, if any, towards `pol`.
  void tick(double t_s, const std::optional<control::AzEl>& demand, const control::AzEl& rate_deg_s,
            const control::PolDemand& pol = {});

  [[nodiscard]] double max_duty_after_fault() const { return max_duty_after_fault_; }
  [[nodiscard]] const AxisPlant& az_plant() const { return rig_->plants().az(); }
  [[nodiscard]] const AxisPlant& el_plant() const { return rig_->plants().el(); }
  /// The polarisation plant; nullptr without one.
  [[nodiscard]] const AxisPlant* pol_plant() const { return rig_->pol_plant(); }
  [[nodiscard]] const control::StationController& station() const { return station_.station(); }
  /// The station's polarisation axis; nullptr without one.
  [[nodiscard]] const control::PolAxis* pol() const { return station_.pol(); }
  [[nodiscard]] proto::HubCounters hub_counters() const { return rig_->hub().counters(); }
  /// Each axis's time driven against its brake plant (0 without one).
  [[nodiscard]] std::array<double, 2> brake_pulled_against_s() const {
    std::array<double, 2> out{};
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (const BrakePlant* b = rig_->brake(i)) out.at(i) = b->pulled_against_s();
    }
    return out;
  }

  /// Adds each axis's first latched fault to `out`: "az: stall at 12.3 s: …".
  void collect_faults(std::vector<std::string>& out, double t_s);

 private:
  StationLoop(const StationSimSetup& setup, SimulatedStation sim)
      : rig_(std::move(sim.rig)),
        station_(station_control_config(setup),
                 control::AzEl{setup.plant.az.start_deg, setup.plant.el.start_deg},
                 setup.station.corrections, std::move(sim.ports)) {}

  std::shared_ptr<const PlantRig> rig_;
  control::PortedStation station_;
  std::array<bool, 3> fault_reported_{};
  double max_duty_after_fault_ = 0.0;
};

}  // namespace azt::sim
