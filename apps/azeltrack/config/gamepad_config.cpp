#include "config/gamepad_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {

std::optional<GamepadConfig> read_gamepad(const ConfigFile& file) {
  const ConfigSection s = file.section("gamepad");
  const auto device = s.text("device");
  if (!device) return std::nullopt;
  // The schema has checked the ranges (config/schema_station_io_keys.cpp).
  GamepadConfig g;
  g.device = *device;
  if (g.device.empty()) s.fail("device", "is empty (leave the key out for no game pad)");
  g.dead_zone = s.number("dead_zone").value_or(g.dead_zone);
  g.speed = s.number("speed").value_or(g.speed);
  g.park_slot = static_cast<int>(s.integer("park_slot").value_or(g.park_slot));
  return g;
}

}  // namespace azt::app
