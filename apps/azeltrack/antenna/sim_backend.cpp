// The `sim` backend: the one station backend on the simulated plants and EncoderHub link,
// stepped in real time by the daemon's tick.
#include "antenna/antenna_backend.hpp"
#include "antenna/station_backend.hpp"
#include "azt/sim/sim_station_ports.hpp"

namespace azt::app {

std::unique_ptr<AntennaBackend> make_sim_backend(const DaemonConfig& config) {
  auto ports = sim::make_sim_station_ports(config.sim);
  std::string describe = ports.sensors[0]->describe();
  return make_station_backend(sim::station_control_config(config.simulated()), config.start_mount(),
                              config.station.corrections, std::move(ports), std::move(describe));
}

}  // namespace azt::app
