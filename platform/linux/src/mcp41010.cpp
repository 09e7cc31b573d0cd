#include "azt/linux/mcp41010.hpp"

#include "azt/control/setpoint_drive.hpp"

namespace azt::linux_os {

Result<bool> Mcp41010Writer::write(std::uint8_t wiper) {
  const auto frame = control::mcp41010_write_frame(wiper);
  if (auto r = bus_.transfer(frame, {}); !r) {
    return fail("MCP41010 wiper " + std::to_string(wiper) + ": " + r.error().message);
  }
  return true;
}

}  // namespace azt::linux_os
