#include "azt/linux/serial_port.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace azt::linux_os {
namespace {

std::string errno_text() { return std::strerror(errno); }

Result<speed_t> termios_speed(unsigned baud) {
  switch (baud) {
    case 600:
      return speed_t{B600};
    case 1200:
      return speed_t{B1200};
    case 2400:
      return speed_t{B2400};
    case 4800:
      return speed_t{B4800};
    case 9600:
      return speed_t{B9600};
    case 19200:
      return speed_t{B19200};
    case 38400:
      return speed_t{B38400};
    case 57600:
      return speed_t{B57600};
    case 115200:
      return speed_t{B115200};
    default:
      return fail("baud " + std::to_string(baud) +
                  " is not one of 600 1200 2400 4800 9600 19200 38400 57600 115200");
  }
}

}  // namespace

Result<bool> make_raw_serial(int fd, unsigned baud) {
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) return fail("not a serial device: " + errno_text());
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS);
  if (baud != 0) {
    auto speed = termios_speed(baud);
    if (!speed) return speed.error();
    cfsetispeed(&tio, *speed);
    cfsetospeed(&tio, *speed);
  }
  if (tcsetattr(fd, TCSANOW, &tio) != 0) return fail("cannot configure: " + errno_text());
  return true;
}

Result<int> open_serial_device(const std::string& device, unsigned baud) {
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fail(device + ": " + errno_text());
  if (::ioctl(fd, TIOCEXCL) != 0) {
    const auto why = errno_text();
    ::close(fd);
    return fail(device + ": cannot open exclusively: " + why);
  }
  if (auto raw = make_raw_serial(fd, baud); !raw) {
    ::close(fd);
    return fail(device + ": " + raw.error().message);
  }
  return fd;
}

}  // namespace azt::linux_os
