#pragma once
// I2C through the kernel's i2c-dev driver (Documentation/i2c/dev-interface.rst; on a Raspberry
// Pi `dtparam=i2c_arm=on` makes /dev/i2c-1). I2cBus is the seam the chip drivers (ADS1115) talk
// to, so tests replace the bus with a recording fake; I2cDevBus is the real one.

#include <cstdint>
#include <optional>
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

/// One SMBus transfer (the kernel's I2C_SMBUS ioctl): the form a register chip's transaction
/// takes on an adapter that does only SMBus (the kernel's i2c-stub; a PC's SMBus controller).
/// The bytes on the wire are the same as the plain transfers': "write word data" is START,
/// address+W, the register, two bytes, STOP (the ADS1115's register write, SBAS444 §9.5.3);
/// "read word data" is the register written, a repeated START, two bytes read (its register
/// read). SMBus sends a word's low byte first, so a chip's first byte is the word's low byte.
struct SmbusTransfer {
  bool read = false;
  std::uint8_t command = 0;  ///< the register (the chip's pointer)
  std::uint32_t size = 0;    ///< I2C_SMBUS_BYTE (a pointer write alone) or I2C_SMBUS_WORD_DATA
  std::uint16_t word = 0;    ///< the two data bytes of a word write, first byte low
};

/// The SMBus form of a write: one byte sets the pointer, three write a register's two bytes;
/// other lengths have none (an error saying so).
Result<SmbusTransfer> smbus_write_form(std::span<const std::uint8_t> bytes);
/// The SMBus form of a two-byte read of the register `pointer` last written: SMBus has no
/// plain read of two bytes, so the read names the register again. An error without a pointer
/// or for another length.
Result<SmbusTransfer> smbus_read_form(std::optional<std::uint8_t> pointer, std::size_t length);

class I2cDevBus final : public I2cBus {
 public:
  /// Opens `path` (e.g. /dev/i2c-1). An adapter that does plain I2C transfers gets them; one
  /// that does only SMBus word transfers gets their SMBus forms (smbus_write_form); one that
  /// does neither is refused, naming the path.
  /// Fails naming the path: a missing device (I2C not enabled), no permission (not in group
  /// `i2c`), or a file that is not an i2c-dev device (the ioctls fail).
  static Result<I2cDevBus> open(const std::string& path);

  /// Each call is one I2C_RDWR message. Errors name the path and the address; a device that
  /// does not acknowledge gives "Remote I/O error (nothing answers at this address?)".
  Result<bool> write(std::uint8_t addr, std::span<const std::uint8_t> bytes) override;
  Result<bool> read(std::uint8_t addr, std::span<std::uint8_t> bytes) override;

  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  I2cDevBus(UniqueFd fd, std::string path, bool smbus_only)
      : fd_(std::move(fd)), path_(std::move(path)), smbus_only_(smbus_only) {}
  Result<bool> message(std::uint8_t addr, std::uint16_t flags, std::span<std::uint8_t> bytes);
  Result<std::uint16_t> smbus(std::uint8_t addr, const Result<SmbusTransfer>& form);

  UniqueFd fd_;
  std::string path_;
  bool smbus_only_ = false;
  std::optional<std::uint8_t> smbus_addr_;     ///< the address I2C_SLAVE last chose
  std::optional<std::uint8_t> smbus_pointer_;  ///< the register last written there
};

}  // namespace azt::linux_os
