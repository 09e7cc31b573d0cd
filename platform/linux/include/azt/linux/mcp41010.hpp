#pragma once
// The MCP41010 digital pot that stands in for a rotator box's control pot (control/
// setpoint_drive.hpp), on the SPI seam: one 2-byte write per wiper code, nothing read back (the
// chip has no SO pin).

#include <cstdint>

#include "azt/linux/spi_device.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

class Mcp41010Writer {
 public:
  explicit Mcp41010Writer(SpiBus& bus) : bus_(bus) {}

  /// Writes the wiper code (0–255) to pot 0: command byte 0x11, then the code.
  Result<bool> write(std::uint8_t wiper);

 private:
  SpiBus& bus_;
};

}  // namespace azt::linux_os
