#pragma once
// I2C through the kernel's i2c-dev driver (Documentation/i2c/dev-interface.rst; on a Raspberry
// Pi `dtparam=i2c_arm=on` makes /dev/i2c-1). I2cBus is the seam the chip drivers (ADS1115) talk
// to, so tests replace the bus with a recording fake; I2cDevBus is the real one.

#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "azt/linux/unique_fd.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

class I2cBus {
 public:
  virtual ~I2cBus() = default;
  /// One write transaction to the 7-bit address `addr`: START, address+W, the bytes, STOP.
  /// Result<bool> is this code base's Result<void>: true or an error.
  virtual Result<bool> write(std::uint8_t addr, std::span<const std::uint8_t> bytes) = 0;
  /// One read transaction from `addr`: START, address+R, bytes.size() bytes, STOP.
  virtual Result<bool> read(std::uint8_t addr, std::span<std::uint8_t> bytes) = 0;

 protected:
  I2cBus() = default;
  I2cBus(const I2cBus&) = default;
  I2cBus& operator=(const I2cBus&) = default;
  I2cBus(I2cBus&&) = default;
  I2cBus& operator=(I2cBus&&) = default;
};

class I2cDevBus final : public I2cBus {
 public:
  /// Opens `path` (e.g. /dev/i2c-1) and checks that the adapter does plain I2C transfers.
  /// Fails naming the path: a missing device (I2C not enabled), no permission (not in group
  /// `i2c`), or a file that is not an i2c-dev device (the ioctls fail).
  static Result<I2cDevBus> open(const std::string& path);

  /// Each call is one I2C_RDWR message. Errors name the path and the address; a device that
  /// does not acknowledge gives "Remote I/O error (nothing answers at this address?)".
  Result<bool> write(std::uint8_t addr, std::span<const std::uint8_t> bytes) override;
  Result<bool> read(std::uint8_t addr, std::span<std::uint8_t> bytes) override;

  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  I2cDevBus(UniqueFd fd, std::string path) : fd_(std::move(fd)), path_(std::move(path)) {}
  Result<bool> message(std::uint8_t addr, std::uint16_t flags, std::span<std::uint8_t> bytes);

  UniqueFd fd_;
  std::string path_;
};

}  // namespace azt::linux_os
