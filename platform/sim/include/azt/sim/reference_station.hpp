#pragma once

#include "azt/sim/station_sim.hpp"

namespace azt::sim {

/// The control issue's reference plant, wired as a station: az 1.5°/s, el 1.0°/s, τ 0.3 s,
/// backlash 0.05°, stiction 0.1, `bits`-bit encoders on both axes, 0–360° azimuth and 0–90°
/// elevation, the controllers told the plant's rate, time constant, stiction and play (as a user
/// configures them), starting at az 180°, el 10°.
StationSimSetup reference_station(int bits, double window_deg);

}  // namespace azt::sim
