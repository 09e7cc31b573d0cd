#pragma once
// An SPI bus for the `hardware` backend's tests (pol_hardware_test.cpp, actuator_pot_test.cpp):
// an MCP3008 answering a code the test computes from its plant, and an MCP41010 whose wiper the
// backend writes.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>

#include "azt/linux/spi_device.hpp"

namespace azt::app::testing {

/// An MCP3008 answering `code` on every channel; an MCP41010's frames set `wiper`.
class CodeSpi final : public linux_os::SpiBus {
 public:
  explicit CodeSpi(std::function<int()> code, std::function<void(int)> wiper = {})
      : code_(std::move(code)), wiper_(std::move(wiper)) {}
  Result<bool> transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) override {
    if (tx.size() == 2 && wiper_) wiper_(tx[1]);
    if (tx.size() == 3 && rx.size() == 3) {
      const auto c = static_cast<unsigned>(std::clamp(code_(), 0, 1023));
      rx[0] = 0;
      rx[1] = static_cast<std::uint8_t>((c >> 8) & 0x3U);
      rx[2] = static_cast<std::uint8_t>(c & 0xFFU);
    }
    return true;
  }

 private:
  std::function<int()> code_;
  std::function<void(int)> wiper_;
};

}  // namespace azt::app::testing
