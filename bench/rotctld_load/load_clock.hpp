#pragma once
// The one clock of rotctld_load: deadlines, latencies and the run's end.

#include <chrono>

namespace rotctld_load {

using Clock = std::chrono::steady_clock;

}  // namespace rotctld_load
