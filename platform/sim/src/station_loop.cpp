#include "azt/sim/station_loop.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace azt::sim {

StationLoop::StationLoop(const StationSimSetup& setup, std::unique_ptr<SimulatedHub> hub)
    : StationLoop(setup, make_simulated_station(
                             setup.plant, hub ? std::move(hub) : make_model_hub(setup.plant))) {}

void StationLoop::tick(double t_s, const std::optional<control::AzEl>& demand,
                       const control::AzEl& rate_deg_s) {
  control::Demand d;
  d.position = demand;
  station_.tick(t_s, d, rate_deg_s);
  const control::Duties duties = station().duties();
  const std::array<double, 2> duty{duties.az, duties.el};
  const std::array<control::AxisStatus, 2> axes{station().az(), station().el()};
  for (std::size_t i = 0; i < 2; ++i) {
    if (axes.at(i).fault != control::FaultKind::None) {
      max_duty_after_fault_ = std::max(max_duty_after_fault_, std::fabs(duty.at(i)));
    }
  }
}
void StationLoop::collect_faults(std::vector<std::string>& out, double t_s) {
  const std::pair<const char*, control::AxisStatus> axes[] = {{"az", station().az()},
                                                              {"el", station().el()}};
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& [name, axis] = axes[i];
    if (axis.fault != control::FaultKind::None && !fault_reported_[i]) {
      fault_reported_[i] = true;
      out.push_back(std::string(name) + ": " + std::string(control::to_string(axis.fault)) +
                    " at " + std::to_string(t_s) + " s: " + axis.reason);
    }
  }
}
}  // namespace azt::sim
