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

}  // namespace

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
  if ((funcs & I2C_FUNC_I2C) == 0) {
    return fail(path + ": the adapter does not do plain I2C transfers (I2C_RDWR), only SMBus");
  }
  return I2cDevBus(std::move(fd), path);
}

Result<bool> I2cDevBus::write(std::uint8_t addr, std::span<const std::uint8_t> bytes) {
  // I2C_RDWR takes a non-const buffer for both directions; a write only reads from it.
  return message(addr, 0,
                 std::span<std::uint8_t>(const_cast<std::uint8_t*>(bytes.data()), bytes.size()));
}

Result<bool> I2cDevBus::read(std::uint8_t addr, std::span<std::uint8_t> bytes) {
  return message(addr, I2C_M_RD, bytes);
}

Result<bool> I2cDevBus::message(std::uint8_t addr, std::uint16_t flags,
                                std::span<std::uint8_t> bytes) {
  const std::string where = path_ + " addr " + hex_addr(addr);
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
  if (::ioctl(fd_.get(), I2C_RDWR, &data) < 0) {
    const int err = errno;
    // No acknowledge of the address: EREMOTEIO from most adapters (the Pi's bcm2835 among
    // them), ENXIO from some.
    const bool nack = err == EREMOTEIO || err == ENXIO;
    return fail(where + ": " + std::strerror(err) +
                (nack ? " (nothing answers at this address?)" : ""));
  }
  return true;
}

}  // namespace azt::linux_os
