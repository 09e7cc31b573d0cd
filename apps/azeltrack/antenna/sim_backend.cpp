// The `sim` backend: the one station backend on the simulated plants, stepped in real time by the
// daemon's tick, read through the plain EncoderHub model or, with [sim] hub = "firmware", through
// the hub firmware on a simulated ATmega328P (docs/encoder-hub.md).
#include <filesystem>

#include "antenna/antenna_backend.hpp"
#include "antenna/station_backend.hpp"
#include "azt/avr/firmware_station_ports.hpp"
#include "azt/sim/sim_station_ports.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

/// [sim] hub_firmware, or the ELF the build puts beside the program (build/firmware/).
std::string firmware_path(const SimHubConfig& hub) {
  if (!hub.elf.empty()) return hub.elf;
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return (self.parent_path() / "firmware" / "encoder-hub.elf").string();
}

ports::StationPorts sim_ports(const DaemonConfig& config) {
  if (!config.sim_hub.firmware) return sim::make_sim_station_ports(config.sim);
  const std::string elf = firmware_path(config.sim_hub);
  auto station = avr::make_firmware_station(config.sim, elf);
  if (!station) throw UsageError("[sim] hub_firmware: " + station.error().message);
  return std::move(station.value().ports);
}

}  // namespace

std::unique_ptr<AntennaBackend> make_sim_backend(const DaemonConfig& config) {
  auto ports = sim_ports(config);
  std::string describe = ports.sensors[0]->describe();
  return make_station_backend(sim::station_control_config(config.simulated()), config.start_mount(),
                              config.station.corrections, std::move(ports), std::move(describe));
}

}  // namespace azt::app
