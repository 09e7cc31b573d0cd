#include "azt/linux/i2c_device.hpp"

#include <fcntl.h>
#include <linux/i2c-dev.h>
#include <linux/i2c.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>

namespace azt::linux_os {
namespace {

std::string open_hint(int err) {
  if (err == ENOENT) return " (is I2C enabled? dtparam=i2c_arm=on)";
  if (err == EACCES) return " (is the user in group i2c?)";
  return "";
}

std::string hex_addr(std::uint8_t addr) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02x", static_cast<unsigned>(addr));
  return text;
}

std::string where_at(const std::string& path, std::uint8_t addr) {
  return path + " addr " + hex_addr(addr);
}

std::string failure(const std::string& where, int err) {
  // No acknowledge of the address: EREMOTEIO from most adapters (the Pi's bcm2835 among
  // them), ENXIO from some.
  const bool nack = err == EREMOTEIO || err == ENXIO;
  return where + ": " + std::strerror(err) + (nack ? " (nothing answers at this address?)" : "");
}

}  // namespace

Result<SmbusTransfer> smbus_write_form(std::span<const std::uint8_t> bytes) {
  if (bytes.size() == 1) return SmbusTransfer{false, bytes[0], I2C_SMBUS_BYTE, 0};
  if (bytes.size() == 3) {
    const auto word = static_cast<std::uint16_t>(bytes[1] | (bytes[2] << 8U));
    return SmbusTransfer{false, bytes[0], I2C_SMBUS_WORD_DATA, word};
  }
  return fail("a write of " + std::to_string(bytes.size()) +
              " bytes has no SMBus form (1: a register pointer, 3: a register's two bytes)");
}

Result<SmbusTransfer> smbus_read_form(std::optional<std::uint8_t> pointer, std::size_t length) {
  if (length != 2) {
    return fail("a read of " + std::to_string(length) + " bytes has no SMBus form (only 2)");
  }
  if (!pointer) return fail("an SMBus read needs the register pointer written first");
  return SmbusTransfer{true, *pointer, I2C_SMBUS_WORD_DATA, 0};
}

Result<I2cDevBus> I2cDevBus::open(const std::string& path) {
  UniqueFd fd(::open(path.c_str(), O_RDWR | O_CLOEXEC));
  if (!fd.valid()) {
    const int err = errno;
    return fail(path + ": " + std::strerror(err) + open_hint(err));
  }
  unsigned long funcs = 0;  // NOLINT(google-runtime-int): the ioctl's own type
  // A regular file or another device answers with ENOTTY.
  if (::ioctl(fd.get(), I2C_FUNCS, &funcs) != 0) {
    const int err = errno;
    return fail(path + (err == ENOTTY ? ": not an i2c-dev device" : ": cannot query the adapter") +
                " (I2C_FUNCS: " + std::strerror(err) + ")");
  }
  if ((funcs & I2C_FUNC_I2C) != 0) return I2cDevBus(std::move(fd), path, false);
  if ((funcs & I2C_FUNC_SMBUS_WORD_DATA) == I2C_FUNC_SMBUS_WORD_DATA &&
      (funcs & I2C_FUNC_SMBUS_WRITE_BYTE) != 0) {
    return I2cDevBus(std::move(fd), path, true);
  }
  return fail(path + ": the adapter does neither plain I2C transfers (I2C_RDWR) nor SMBus " +
              "word transfers");
}

Result<bool> I2cDevBus::write(std::uint8_t addr, std::span<const std::uint8_t> bytes) {
  if (smbus_only_) {
    auto done = smbus(addr, smbus_write_form(bytes));
    if (!done) return done.error();
    smbus_pointer_ = bytes[0];
    return true;
  }
  // I2C_RDWR takes a non-const buffer for both directions; a write only reads from it.
  return message(addr, 0,
                 std::span<std::uint8_t>(const_cast<std::uint8_t*>(bytes.data()), bytes.size()));
}

Result<bool> I2cDevBus::read(std::uint8_t addr, std::span<std::uint8_t> bytes) {
  if (!smbus_only_) return message(addr, I2C_M_RD, bytes);
  // A pointer written at another address is not this chip's.
  const auto pointer = smbus_addr_ == addr ? smbus_pointer_ : std::nullopt;
  auto word = smbus(addr, smbus_read_form(pointer, bytes.size()));
  if (!word) return word.error();
  bytes[0] = static_cast<std::uint8_t>(*word & 0xFFU);
  bytes[1] = static_cast<std::uint8_t>(*word >> 8U);
  return true;
}

Result<std::uint16_t> I2cDevBus::smbus(std::uint8_t addr, const Result<SmbusTransfer>& form) {
  const std::string where = where_at(path_, addr);
  if (!form) return fail(where + ": " + form.error().message);
  if (addr > 0x7F) return fail(where + ": not a 7-bit address");
  if (smbus_addr_ != addr) {
    // I2C_SLAVE, not _FORCE: a chip a kernel driver has claimed is not ours to talk to.
    if (::ioctl(fd_.get(), I2C_SLAVE, static_cast<unsigned long>(addr)) != 0) {  // NOLINT
      return fail(failure(where + " (I2C_SLAVE)", errno));
    }
    smbus_addr_ = addr;
    smbus_pointer_.reset();
  }
  i2c_smbus_data data{};
  data.word = form->word;
  i2c_smbus_ioctl_data call{};
  call.read_write = form->read ? I2C_SMBUS_READ : I2C_SMBUS_WRITE;
  call.command = form->command;
  call.size = form->size;
  call.data = form->size == I2C_SMBUS_BYTE ? nullptr : &data;
  if (::ioctl(fd_.get(), I2C_SMBUS, &call) < 0) return fail(failure(where, errno));
  return data.word;
}

Result<bool> I2cDevBus::message(std::uint8_t addr, std::uint16_t flags,
                                std::span<std::uint8_t> bytes) {
  const std::string where = where_at(path_, addr);
  if (addr > 0x7F) return fail(where + ": not a 7-bit address");
  if (bytes.size() > std::numeric_limits<std::uint16_t>::max()) {
    return fail(where + ": " + std::to_string(bytes.size()) + " bytes is too long a message");
  }
  i2c_msg msg{};
  msg.addr = addr;
  msg.flags = flags;
  msg.len = static_cast<std::uint16_t>(bytes.size());
  msg.buf = bytes.data();
  i2c_rdwr_ioctl_data data{};
  data.msgs = &msg;
  data.nmsgs = 1;
  if (::ioctl(fd_.get(), I2C_RDWR, &data) < 0) return fail(failure(where, errno));
  return true;
}

}  // namespace azt::linux_os
