#include "azt/sim/station_loop.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace azt::sim {

StationLoop::StationLoop(const StationSimSetup& setup, std::unique_ptr<SimulatedHub> hub)
    : StationLoop(setup, make_simulated_station(
                             setup.plant, hub ? std::move(hub) : make_model_hub(setup.plant))) {}

namespace {

/// Each axis's status: az, el, and pol when the station has one.
std::vector<std::pair<const char*, control::AxisStatus>> axis_statuses(
    const control::StationController& station, const control::PolAxis* pol) {
  std::vector<std::pair<const char*, control::AxisStatus>> out{{"az", station.az()},
                                                               {"el", station.el()}};
  if (pol) out.emplace_back("pol", pol->axis().status());
  return out;
}

}  // namespace

void StationLoop::tick(double t_s, const std::optional<control::AzEl>& demand,
                       const control::AzEl& rate_deg_s, const control::PolDemand& pol) {
  control::Demand d;
  d.position = demand;
  station_.tick(t_s, d, rate_deg_s, pol);
  for (const auto& [name, axis] : axis_statuses(station(), this->pol())) {
    if (axis.fault != control::FaultKind::None) {
      max_duty_after_fault_ = std::max(max_duty_after_fault_, std::fabs(axis.duty));
    }
  }
}

void StationLoop::collect_faults(std::vector<std::string>& out, double t_s) {
  const auto axes = axis_statuses(station(), pol());
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const auto& [name, axis] = axes[i];
    if (axis.fault != control::FaultKind::None && !fault_reported_.at(i)) {
      fault_reported_.at(i) = true;
      out.push_back(std::string(name) + ": " + std::string(control::to_string(axis.fault)) +
                    " at " + std::to_string(t_s) + " s: " + axis.reason);
    }
  }
}

}  // namespace azt::sim
