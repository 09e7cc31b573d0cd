#pragma once
// Plant faults injected as their times come, earliest first, each once: the virtual-time
// simulations and the daemon's simulated antenna share it.

#include <cstddef>
#include <vector>

#include "azt/sim/plant_setup.hpp"
#include "azt/sim/sim_antenna.hpp"

namespace azt::sim {

class FaultSchedule {
 public:
  explicit FaultSchedule(std::vector<ScheduledFault> faults);
  /// Injects into `antenna` every fault due at `t_s` (seconds from the start) not yet injected.
  void inject_due(double t_s, SimAntenna& antenna);

 private:
  std::vector<ScheduledFault> faults_;  ///< sorted by at_s
  std::size_t next_ = 0;
};

}  // namespace azt::sim
