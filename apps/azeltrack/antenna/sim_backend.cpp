// The `sim` backend: the one station backend on the simulated plants and EncoderHub link,
// stepped in real time by the daemon's tick.
#include "antenna/antenna_backend.hpp"
#include "antenna/station_backend.hpp"
#include "azt/sim/sim_station_ports.hpp"

namespace azt::app {

std::unique_ptr<AntennaBackend> make_sim_backend(const DaemonConfig& config) {
  const sim::StationSimSetup& s = config.sim.setup;
  auto ports = sim::make_sim_station_ports(s);
  std::string describe = ports.sensors[0]->describe();
  return make_station_backend(sim::station_control_config(s),
                              control::AzEl{s.az_plant.start_deg, s.el_plant.start_deg},
                              s.station.corrections, std::move(ports), std::move(describe));
}

}  // namespace azt::app
