// The `sim` backend: the one station backend on the simulated plants, stepped in real time by the
// daemon's tick, read through the plain EncoderHub model or, with [sim] hub = "firmware", through
// the hub firmware on a simulated ATmega328P (docs/encoder-hub.md); with [sim.az|el] brake and
// motor_heating, the plants' brakes and windings through the same ports as a real axis's.
#include "antenna/antenna_backend.hpp"
#include "antenna/sim_hub.hpp"
#include "antenna/station_backend.hpp"
#include "azt/sim/simulated_station.hpp"

namespace azt::app {

std::unique_ptr<AntennaBackend> make_sim_backend(const DaemonConfig& config,
                                                 std::shared_ptr<const sim::PlantRig>* truth) {
  auto station = sim::make_simulated_station(config.sim, make_sim_hub(config.sim, config.sim_hub));
  if (truth != nullptr) *truth = station.rig;
  std::string describe = station.rig->hub().describe();
  // [sim.az|el] brake and motor_heating: what the station drives and reads besides the hub.
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string axis = i == 0 ? "az: " : "el: ";
    if (const auto& brake = station.ports.brakes.at(i)) describe += "; " + axis + brake->describe();
    if (const auto& motor = station.ports.motor_sensors.at(i))
      describe += "; " + axis + motor->describe();
  }
  return make_station_backend(sim::station_control_config(config.simulated()), config.start_mount(),
                              config.station.corrections, std::move(station.ports),
                              std::move(describe));
}

}  // namespace azt::app
