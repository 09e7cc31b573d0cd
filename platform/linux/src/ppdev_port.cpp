#include "azt/linux/ppdev_port.hpp"

#include <fcntl.h>
#include <linux/parport.h>
#include <linux/ppdev.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <cstring>

namespace azt::linux_os {

static_assert(kParportControlStrobe == PARPORT_CONTROL_STROBE);
static_assert(kParportControlAutofeed == PARPORT_CONTROL_AUTOFD);

namespace {

std::string open_hint(int err) {
  if (err == ENOENT) return " (is the ppdev module loaded? modprobe ppdev)";
  if (err == EACCES) return " (is the user in group lp?)";
  return "";
}

}  // namespace

Result<PpdevPort> PpdevPort::open(const std::string& path) {
  UniqueFd fd(::open(path.c_str(), O_RDWR | O_CLOEXEC));
  if (!fd.valid()) {
    const int err = errno;
    return fail(path + ": " + std::strerror(err) + open_hint(err));
  }
  // A regular file or another device answers with ENOTTY.
  if (::ioctl(fd.get(), PPCLAIM) != 0) {
    const int err = errno;
    return fail(path +
                (err == ENOTTY ? ": not a parallel port device" : ": cannot claim the port") +
                " (PPCLAIM: " + std::strerror(err) + ")");
  }
  PpdevPort port(std::move(fd), path);  // from here on the destructor releases the claim
  int input = 1;
  if (::ioctl(port.fd_.get(), PPDATADIR, &input) != 0) {
    return fail(path + ": cannot switch the data lines to input (PPDATADIR: " +
                std::strerror(errno) + "; is the port in PS/2, EPP or ECP mode?)");
  }
  return port;
}

PpdevPort& PpdevPort::operator=(PpdevPort&& other) noexcept {
  if (this != &other) {
    release();
    fd_ = std::move(other.fd_);
    path_ = std::move(other.path_);
  }
  return *this;
}

PpdevPort::~PpdevPort() { release(); }

void PpdevPort::release() {
  if (fd_.valid()) ::ioctl(fd_.get(), PPRELEASE);
  fd_.reset();
}

Result<proto::ParallelSample> PpdevPort::sample() {
  unsigned char data = 0;
  unsigned char control = 0;
  if (::ioctl(fd_.get(), PPRDATA, &data) != 0) {
    return fail(path_ + ": PPRDATA: " + std::strerror(errno));
  }
  if (::ioctl(fd_.get(), PPRCONTROL, &control) != 0) {
    return fail(path_ + ": PPRCONTROL: " + std::strerror(errno));
  }
  return parallel_sample_from_registers(data, control);
}

}  // namespace azt::linux_os
