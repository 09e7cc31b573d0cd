#include "antenna/sim_hub.hpp"

#include <filesystem>
#include <string>

#include "azt/avr/firmware_hub.hpp"
#include "azt/sim/simulated_station.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

/// [sim] hub_firmware, else the ELF the build puts beside the program (build/firmware/), else
/// the package's copy (/usr/share/azeltrack/firmware, AZT_FIRMWARE_DIR).
std::string firmware_path(const SimHubConfig& hub) {
  if (!hub.elf.empty()) return hub.elf;
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  auto beside = self.parent_path() / "firmware" / "encoder-hub.elf";
  if (std::filesystem::exists(beside, ec)) return beside.string();
  return std::string(AZT_FIRMWARE_DIR) + "/encoder-hub.elf";
}

}  // namespace

std::unique_ptr<sim::SimulatedHub> make_sim_hub(const sim::PlantSetup& plant,
                                                const SimHubConfig& hub) {
  if (!hub.firmware) return sim::make_model_hub(plant);
  auto firmware = avr::FirmwareHub::load(plant, firmware_path(hub));
  if (!firmware) throw UsageError("[sim] hub_firmware: " + firmware.error().message);
  return std::move(firmware).value();
}

}  // namespace azt::app
