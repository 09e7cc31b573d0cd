#pragma once
// A parallel port read as the FODTRACK interface (proto/fodtrack.hpp) through the kernel's
// ppdev driver (Documentation/driver-api/parport.rst, /dev/parportN): the data lines switched to
// input, STROBE and AUTOFEED read from the control register, sampled by polling.
//
// Polarity. On a PC port the control register's STROBE (bit 0, pin 1), AUTOFEED (bit 1, pin 14)
// and SELECT IN (bit 3, pin 17) are inverted by the port hardware: a 1 in the register is a low
// pin, and these lines are active low, so a 1 is an asserted line. ppdev passes the register as
// it is (include/uapi/linux/parport.h: PARPORT_CONTROL_STROBE 0x1, PARPORT_CONTROL_AUTOFD 0x2).
// Hamlib's fodtrack backend, what the tracking programs drive, writes its wanted bits XORed with
// 0x0B through par_write_control, which XORs 0x0B once more: the register it writes holds STROBE
// = 1 during the pulse and AUTOFD = 1 for azimuth. So register bit set = asserted = true in
// ParallelSample, with no inversion here: strobe true while the data is valid, autofeed true for
// azimuth, as FodtrackDecoder expects.
//
// Two limits to know before wiring a port to a tracking PC:
// - parport_pc (every PC-style port) answers PPRCONTROL from the driver's soft copy of what this
//   host last wrote ("Use soft copy" in parport_pc_read_control), not from the pins, so it does
//   not see another computer driving STROBE and AUTOFEED. Reading them needs a port driver that
//   reads the pins back, or a cable that brings them to status inputs (PPRSTATUS reads the pins).
// - Polling can miss a STROBE pulse. Hamlib holds STROBE for hl_usleep(1): 1 µs asked for, in
//   practice some tens of µs on Linux (timer slack, 50 µs by default, and the ioctl round trips),
//   and as little as 1–2 µs from a program writing the port directly. To see every pulse of
//   width w the poll period must be shorter than w: 20 kHz or more for 50 µs, which user space
//   only manages by busy-polling a core; at a control tick's 100 Hz–1 kHz most pulses are missed.
//   The data lines and AUTOFEED keep the last axis written (Hamlib writes elevation, then
//   azimuth), so the azimuth byte stays readable after its pulse but the elevation byte lives
//   only until the azimuth write. A latch in hardware (the seed's PIC) or the port's interrupt
//   (nACK) is what catches every pulse.

#include <cstdint>
#include <string>
#include <utility>

#include "azt/linux/unique_fd.hpp"
#include "azt/proto/fodtrack.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

/// Control register bits, as PARPORT_CONTROL_* in <linux/parport.h> (checked in ppdev_port.cpp).
inline constexpr std::uint8_t kParportControlStrobe = 0x01;
inline constexpr std::uint8_t kParportControlAutofeed = 0x02;

/// The lines as FodtrackDecoder takes them from the data and control registers as ppdev reads
/// them: a set control bit is an asserted line (see the polarity note above).
inline proto::ParallelSample parallel_sample_from_registers(std::uint8_t data,
                                                            std::uint8_t control) {
  proto::ParallelSample s;
  s.data = data;
  s.strobe = (control & kParportControlStrobe) != 0;
  s.autofeed = (control & kParportControlAutofeed) != 0;
  return s;
}

class PpdevPort {
 public:
  /// Opens `path` (e.g. /dev/parport0), claims the port (PPCLAIM) and switches the data lines to
  /// input (PPDATADIR, which needs a bidirectional port: PS/2, EPP or ECP mode). Fails naming the
  /// path: missing device (ppdev not loaded), no permission (not in group lp), or a file that is
  /// not a parallel port (the ioctls fail).
  static Result<PpdevPort> open(const std::string& path);

  PpdevPort(PpdevPort&& other) noexcept = default;
  PpdevPort& operator=(PpdevPort&& other) noexcept;
  PpdevPort(const PpdevPort&) = delete;
  PpdevPort& operator=(const PpdevPort&) = delete;
  /// Releases the port (PPRELEASE), then closes it.
  ~PpdevPort();

  /// Reads the data lines (PPRDATA) and the control register (PPRCONTROL).
  Result<proto::ParallelSample> sample();

  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  PpdevPort(UniqueFd fd, std::string path) : fd_(std::move(fd)), path_(std::move(path)) {}
  void release();

  UniqueFd fd_;  ///< claimed while valid
  std::string path_;
};

}  // namespace azt::linux_os
