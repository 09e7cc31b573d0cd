#pragma once
// The simulated antenna behind the station's ports (issue 13 §2): two plants and their
// EncoderHub link, stepped in the control loop's time. The drives set the plants' duties; the
// first sensor read at a new time runs the plants for the time since the last one with the
// duties then applied (a late tick is simulated exactly as long as it was late), injects the
// faults that have come due and takes the hub's next frame, which both axes' sensors report.

#include "azt/ports/station_ports.hpp"
#include "azt/sim/station_sim.hpp"

namespace azt::sim {

ports::StationPorts make_sim_station_ports(const PlantSetup& plant);

}  // namespace azt::sim
