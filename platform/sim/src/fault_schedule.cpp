#include "azt/sim/fault_schedule.hpp"

#include <algorithm>
#include <utility>

namespace azt::sim {

FaultSchedule::FaultSchedule(std::vector<ScheduledFault> faults) : faults_(std::move(faults)) {
  std::stable_sort(
      faults_.begin(), faults_.end(),
      [](const ScheduledFault& a, const ScheduledFault& b) { return a.at_s < b.at_s; });
}

void FaultSchedule::inject_due(double t_s, SimAntenna& antenna) {
  for (; next_ < faults_.size() && faults_[next_].at_s <= t_s; ++next_) {
    antenna.inject(faults_[next_].azimuth, faults_[next_].fault);
  }
}

}  // namespace azt::sim
