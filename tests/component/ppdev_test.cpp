// The ppdev FODTRACK input (docs/hardware.md): the register-to-lines mapping, whose polarity
// follows Hamlib's fodtrack writes (register bit set = line asserted), and the real adapter's
// refusals of a missing device and of a file that is not a parallel port.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "azt/linux/ppdev_port.hpp"

namespace azt::linux_os {
namespace {

TEST(ParallelSampleFromRegisters, ControlBitSetIsAssertedLine) {
  // What Hamlib's fodtrack leaves in the control register (PARPORT_CONTROL_STROBE 0x01,
  // PARPORT_CONTROL_AUTOFD 0x02): AUTOFD alone before and after an azimuth pulse, both during
  // it; nothing, then STROBE alone, for elevation.
  const auto az_pulse = parallel_sample_from_registers(0xA5, 0x03);
  EXPECT_EQ(az_pulse.data, 0xA5);
  EXPECT_TRUE(az_pulse.strobe);
  EXPECT_TRUE(az_pulse.autofeed);

  const auto az_idle = parallel_sample_from_registers(0xA5, 0x02);
  EXPECT_FALSE(az_idle.strobe);
  EXPECT_TRUE(az_idle.autofeed);

  const auto el_pulse = parallel_sample_from_registers(0x3C, 0x01);
  EXPECT_EQ(el_pulse.data, 0x3C);
  EXPECT_TRUE(el_pulse.strobe);
  EXPECT_FALSE(el_pulse.autofeed);

  const auto el_idle = parallel_sample_from_registers(0x3C, 0x00);
  EXPECT_FALSE(el_idle.strobe);
  EXPECT_FALSE(el_idle.autofeed);
}

TEST(ParallelSampleFromRegisters, OtherControlBitsAreIgnored) {
  // INIT (0x04), SELECT IN (0x08), IRQ enable (0x10) and the direction bit (0x20) say nothing
  // about FODTRACK.
  const auto s = parallel_sample_from_registers(0xFF, 0x3C);
  EXPECT_EQ(s.data, 0xFF);
  EXPECT_FALSE(s.strobe);
  EXPECT_FALSE(s.autofeed);
}

TEST(ParallelSampleFromRegisters, FeedsTheFodtrackDecoder) {
  // An azimuth pulse read through the mapping latches the byte as azimuth in the decoder.
  auto scale = proto::FodtrackScale::make(360.0, 90.0);
  ASSERT_TRUE(scale.ok());
  proto::FodtrackDecoder decoder(*scale);
  EXPECT_FALSE(decoder.feed(parallel_sample_from_registers(255, 0x02)).has_value());
  EXPECT_TRUE(decoder.feed(parallel_sample_from_registers(255, 0x03)).has_value());
  ASSERT_TRUE(decoder.az_deg().has_value());
  EXPECT_DOUBLE_EQ(*decoder.az_deg(), 360.0);
  EXPECT_FALSE(decoder.el_deg().has_value());
}

TEST(PpdevPortOpen, MissingDeviceNamesThePathAndTheHint) {
  auto port = PpdevPort::open("/dev/azt-no-such-parport9");
  ASSERT_FALSE(port.ok());
  EXPECT_EQ(port.error().message,
            "/dev/azt-no-such-parport9: No such file or directory (is the ppdev module loaded? "
            "modprobe ppdev)");
}

TEST(PpdevPortOpen, RefusesARegularFile) {
  const auto file =
      std::filesystem::temp_directory_path() / ("azt_not_a_parport_" + std::to_string(::getpid()));
  std::ofstream(file) << "plain file\n";
  auto port = PpdevPort::open(file.string());
  std::filesystem::remove(file);
  ASSERT_FALSE(port.ok());
  EXPECT_NE(port.error().message.find(file.string() + ": not a parallel port device"),
            std::string::npos)
      << port.error().message;
}

}  // namespace
}  // namespace azt::linux_os
