#pragma once
// A satellite's pass as the sky track the pass planner takes: its look angles every second.

#include <vector>

#include "azt/orbit/satellite.hpp"
#include "azt/track/pass_plan.hpp"
#include "azt/util/result.hpp"

namespace azt::track {

/// The pass sampled every second from its AOS to its LOS (pass times are seconds after `from`);
/// each point's time is its pass time plus `time_offset_s`. The error names the satellite.
Result<std::vector<SkyPoint>> sample_pass(const orbit::Satellite& sat,
                                          const astro::UtcInstant& from, const orbit::Pass& pass,
                                          double dut1_s, const astro::Observer& site,
                                          double time_offset_s = 0.0);

}  // namespace azt::track
