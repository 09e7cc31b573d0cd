#include "azt/linux/spi_device.hpp"

#include <fcntl.h>
#include <linux/spi/spidev.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <cstring>

namespace azt::linux_os {
namespace {

std::string open_hint(int err) {
  if (err == ENOENT) return " (is SPI enabled? dtparam=spi=on)";
  if (err == EACCES) return " (is the user in group spi?)";
  return "";
}

}  // namespace

Result<SpidevBus> SpidevBus::open(const std::string& path, std::uint32_t speed_hz,
                                  std::uint8_t mode) {
  if (mode > 3) return fail(path + ": SPI mode " + std::to_string(mode) + " is not 0-3");
  if (speed_hz == 0) return fail(path + ": SPI clock must be above 0 Hz");
  UniqueFd fd(::open(path.c_str(), O_RDWR | O_CLOEXEC));
  if (!fd.valid()) {
    const int err = errno;
    return fail(path + ": " + std::strerror(err) + open_hint(err));
  }
  std::uint8_t bits = 8;
  std::uint32_t speed = speed_hz;
  // A regular file or another device answers the first ioctl with ENOTTY.
  if (::ioctl(fd.get(), SPI_IOC_WR_MODE, &mode) != 0) {
    const int err = errno;
    return fail(path + (err == ENOTTY ? ": not a spidev device" : ": cannot set the SPI mode") +
                " (SPI_IOC_WR_MODE: " + std::strerror(err) + ")");
  }
  if (::ioctl(fd.get(), SPI_IOC_WR_BITS_PER_WORD, &bits) != 0) {
    return fail(path + ": cannot set 8 bits per word: " + std::strerror(errno));
  }
  if (::ioctl(fd.get(), SPI_IOC_WR_MAX_SPEED_HZ, &speed) != 0) {
    return fail(path + ": cannot set the clock to " + std::to_string(speed_hz) +
                " Hz: " + std::strerror(errno));
  }
  return SpidevBus(std::move(fd), path, speed_hz);
}

Result<bool> SpidevBus::transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) {
  if (!rx.empty() && rx.size() != tx.size()) {
    return fail(path_ + ": SPI transfer of " + std::to_string(tx.size()) + " bytes out but " +
                std::to_string(rx.size()) + " in");
  }
  if (tx.empty()) return true;
  spi_ioc_transfer t{};
  t.tx_buf = reinterpret_cast<std::uintptr_t>(tx.data());
  t.rx_buf = rx.empty() ? 0 : reinterpret_cast<std::uintptr_t>(rx.data());
  t.len = static_cast<std::uint32_t>(tx.size());
  t.speed_hz = speed_hz_;
  t.bits_per_word = 8;
  t.cs_change = 0;  // chip select stays asserted for the whole transfer, released after it
  // SPI_IOC_MESSAGE returns the number of bytes transferred, or -1.
  if (::ioctl(fd_.get(), SPI_IOC_MESSAGE(1), &t) < 0) {
    return fail(path_ + ": SPI transfer: " + std::strerror(errno));
  }
  return true;
}

}  // namespace azt::linux_os
