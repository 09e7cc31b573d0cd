#pragma once
// The simulated antenna behind the station's ports: the drives set
// the plants' duties, the sensors report the hub's frames (plant_rig.hpp says how time runs).
// The hub is the plain model or the firmware on a simulated AVR; the daemon's `sim` backend and
// the virtual-time simulations (station_sim.hpp) build their station the same way.

#include <memory>

#include "azt/ports/station_ports.hpp"
#include "azt/sim/plant_rig.hpp"
#include "azt/sim/plant_setup.hpp"
#include "azt/sim/simulated_hub.hpp"

namespace azt::sim {

/// The ports a station backend drives, and the rig behind them to measure the truth by.
struct SimulatedStation {
  ports::StationPorts ports;
  std::shared_ptr<const PlantRig> rig;
};

/// The plain hub model of `plant`: its frame version, link faults and seed.
std::unique_ptr<SimulatedHub> make_model_hub(const PlantSetup& plant);

SimulatedStation make_simulated_station(const PlantSetup& plant, std::unique_ptr<SimulatedHub> hub);

}  // namespace azt::sim
