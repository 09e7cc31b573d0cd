#pragma once
// A game pad or joystick through Linux input events and libevdev (Debian libevdev-dev; its
// header's notes on non-blocking use): the device opened non-blocking, its descriptor watched by
// the io_context, every queued event read with libevdev_next_event until -EAGAIN, and a dropped
// buffer (SYN_DROPPED) resynchronised with LIBEVDEV_READ_FLAG_SYNC. What it keeps is the pad's
// present state (the core's hands::PadState): the loop reads it at each control tick and never
// waits for the device.

#include <functional>
#include <memory>
#include <string>

#include "azt/hands/pad_state.hpp"
#include "azt/util/result.hpp"

namespace boost::asio {
class io_context;
}  // namespace boost::asio

namespace azt::linux_os {

class EvdevPad {
 public:
  EvdevPad() = default;
  EvdevPad(const EvdevPad&) = delete;
  EvdevPad& operator=(const EvdevPad&) = delete;
  EvdevPad(EvdevPad&&) = delete;
  EvdevPad& operator=(EvdevPad&&) = delete;
  virtual ~EvdevPad() = default;

  /// The state as the last events left it (kept until the pad is gone, then cleared).
  [[nodiscard]] virtual const hands::PadState& state() const = 0;
  /// The device's own name ("Microsoft X-Box 360 pad").
  [[nodiscard]] virtual const std::string& name() const = 0;
  /// False once the device went away (unplugged: ENODEV) or failed; it is then closed.
  [[nodiscard]] virtual bool present() const = 0;
};

/// Opens `path` (a /dev/input/event* node, better its /dev/input/by-id/ link): an error names the
/// path and the reason (no such device, permission, not an input device). `on_lost` is called
/// once, from the loop, when the device goes away.
Result<std::unique_ptr<EvdevPad>> open_evdev_pad(boost::asio::io_context& io,
                                                 const std::string& path,
                                                 std::function<void(const std::string&)> on_lost);

}  // namespace azt::linux_os
