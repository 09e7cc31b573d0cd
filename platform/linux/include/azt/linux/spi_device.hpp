#pragma once
// SPI through the kernel's spidev driver (Documentation/spi/spidev.rst; on a Raspberry Pi
// `dtparam=spi=on` makes /dev/spidev0.0 and /dev/spidev0.1, one per chip select). SpiBus is the
// seam the chip drivers (MCP3008, MCP41010) talk to, so tests replace the bus with a recording
// fake; SpidevBus is the real one.

#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "azt/linux/unique_fd.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

class SpiBus {
 public:
  virtual ~SpiBus() = default;
  /// One full-duplex transfer with chip select held low throughout: clocks out `tx` and clocks
  /// in as many bytes into `rx`. `rx` is either empty (write only: what comes back is dropped)
  /// or exactly as long as `tx`. Result<bool> is this code base's Result<void>: true or an error.
  virtual Result<bool> transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) = 0;

 protected:
  SpiBus() = default;
  SpiBus(const SpiBus&) = default;
  SpiBus& operator=(const SpiBus&) = default;
  SpiBus(SpiBus&&) = default;
  SpiBus& operator=(SpiBus&&) = default;
};

class SpidevBus final : public SpiBus {
 public:
  /// Opens `path` (e.g. /dev/spidev0.0) and sets SPI `mode` (0–3), 8 bits per word and the
  /// clock `speed_hz` (the MCP3008 runs up to 1.35 MHz at 2.7 V, the MCP41010 up to 10 MHz).
  /// Fails naming the path: a missing device (SPI not enabled), no permission (not in group
  /// `spi`), or a file that is not a spidev device (the ioctls fail).
  static Result<SpidevBus> open(const std::string& path, std::uint32_t speed_hz,
                                std::uint8_t mode = 0);

  /// SPI_IOC_MESSAGE(1). spidev's buffer limit is 4096 bytes per transfer by default.
  Result<bool> transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) override;

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::uint32_t speed_hz() const { return speed_hz_; }

 private:
  SpidevBus(UniqueFd fd, std::string path, std::uint32_t speed_hz)
      : fd_(std::move(fd)), path_(std::move(path)), speed_hz_(speed_hz) {}

  UniqueFd fd_;
  std::string path_;
  std::uint32_t speed_hz_;
};

}  // namespace azt::linux_os
