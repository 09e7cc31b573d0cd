// The game pad's libevdev adapter against what this machine has: no /dev/uinput here, so a real
// pad's events are the system test's (docs/hardware.md); here the refusals an operator meets with
// a wrong [gamepad] device: each names the path and the reason, and nothing is opened.
#include "azt/linux/evdev_pad.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>

namespace azt::linux_os {
namespace {

TEST(EvdevPad, AMissingDeviceIsAnErrorNamingThePath) {
  boost::asio::io_context io;
  auto pad = open_evdev_pad(io, "/dev/input/by-id/no-such-pad-event-joystick", nullptr);
  ASSERT_FALSE(pad.ok());
  EXPECT_NE(pad.error().message.find("no-such-pad"), std::string::npos) << pad.error().message;
  EXPECT_NE(pad.error().message.find("No such file"), std::string::npos) << pad.error().message;
}

TEST(EvdevPad, AFileThatIsNotAnInputDeviceIsRefused) {
  boost::asio::io_context io;
  auto pad = open_evdev_pad(io, "/dev/null", nullptr);
  ASSERT_FALSE(pad.ok());
  EXPECT_NE(pad.error().message.find("/dev/null: not an input device"), std::string::npos)
      << pad.error().message;
}

}  // namespace
}  // namespace azt::linux_os
