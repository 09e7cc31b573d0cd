// The `pwm` backend end to end (docs/hardware.md): EncoderHub frames on a pseudo-terminal in, two
// IBT-2 bridges on a fake /sys/class/pwm chip out, the real StationController between. When the
// hub falls silent mid-slew the drives must be off within 200 ms of the last valid frame (R01).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_devices.hpp"
#include "azt/linux/asio.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "station/guarded_antenna.hpp"
#include "support/fake_gpio.hpp"
#include "support/fake_pwm_station.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

class PwmBackendTest : public ::testing::Test {
 protected:
  void SetUp() override { station_.make("azt_pwm_backend"); }
  void TearDown() override { station_.remove(); }

  /// The fake hub sends 12-bit frames; `az_bits` is what [mount.az] says.
  DaemonConfig config(int az_bits = 12) const {
    const std::string text = "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"pwm\"\n" +
                             station_.config_tables() +
                             "[mount.az]\nencoder_bits = " + std::to_string(az_bits) +
                             "\n[mount.el]\nencoder_bits = 12\n" +
                             "[sim.az]\nstart_deg = 180.0\n[sim.el]\nstart_deg = 10.0\n";
    return daemon_config_from(ConfigFile::parse(text, "pwm.toml"));
  }
  void send_frame(double az_deg, double el_deg) const { station_.send_frame(az_deg, el_deg); }
  std::uint64_t duty(int channel) const { return station_.duty(channel); }

  testing::FakePwmStation station_;
};

TEST_F(PwmBackendTest, DrivesTowardsTheTargetAndStopsWhenTheHubFallsSilent) {
  boost::asio::io_context io;
  auto backend = make_pwm_backend(io, config());
  ASSERT_TRUE(backend);
  const auto start = Clock::now();
  const auto seconds = [&start] {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  control::Demand go;
  go.position = control::AzEl{200.0, 10.0};           // 20° clockwise of where the hub says it is
  ASSERT_EQ(::write(station_.master(), "\0", 1), 1);  // the first delimiter
  double last_frame_s = 0.0;
  bool driven = false;
  // 1.5 s of frames every 50 ms (the antenna "does not move": the readings stay at 180°).
  while (seconds() < 1.5) {
    send_frame(180.0, 10.0);
    last_frame_s = seconds();
    io.run_for(std::chrono::milliseconds(25));
    io.restart();
    backend->tick(seconds(), go, control::AzEl{});
    driven = driven || duty(0) > 0;
    EXPECT_EQ(duty(1), 0U) << "both sides of the azimuth bridge driven";
    io.run_for(std::chrono::milliseconds(25));
    io.restart();
    backend->tick(seconds(), go, control::AzEl{});
  }
  EXPECT_TRUE(driven) << "the azimuth bridge was never driven clockwise";
  // Silence: tick every 10 ms until both azimuth PWMs read zero.
  double off_s = -1.0;
  while (seconds() < last_frame_s + 1.0) {
    io.run_for(std::chrono::milliseconds(10));
    io.restart();
    backend->tick(seconds(), go, control::AzEl{});
    if (duty(0) == 0 && duty(1) == 0) {
      off_s = seconds();
      break;
    }
  }
  ASSERT_GE(off_s, 0.0) << "the drive stayed on after the hub fell silent";
  const double after_ms = (off_s - last_frame_s) * 1000.0;
  std::printf("[ timing   ] drive off %.0f ms after the last valid frame\n", after_ms);
  EXPECT_LE(after_ms, 200.0);                              // R01
  EXPECT_FALSE(backend->position(seconds()).has_value());  // no cached angle is served

  // Unplugged: a fault that refuses motion, named (at the next tick that reads the hub).
  station_.close_hub();
  for (int i = 0; i < 50 && backend->faults().empty(); ++i) {
    io.run_for(std::chrono::milliseconds(10));
    io.restart();
    backend->tick(seconds(), go, control::AzEl{});
  }
  ASSERT_FALSE(backend->faults().empty());
  EXPECT_NE(backend->faults().back().find("hub: lost"), std::string::npos)
      << backend->faults().back();
}

// The hub's frames carry its jumpers' bits. Frames whose bits are not [mount.az]'s
// are never read as angles: a fault names both values and the bridge is never driven.
// The hub firmware says when it has no position for an axis (a parity error here;
// docs/encoder-hub.md).
// The daemon shows the reason as that axis's fault and drives nothing until good frames return.
TEST_F(PwmBackendTest, AnAxisErrorFromTheHubIsAFaultNamingItAndNothingIsDriven) {
  boost::asio::io_context io;
  auto backend = make_pwm_backend(io, config());
  const auto start = Clock::now();
  const auto seconds = [&start] {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  control::Demand go;
  go.position = control::AzEl{200.0, 10.0};
  ASSERT_EQ(::write(station_.master(), "\0", 1), 1);
  proto::HubReading bad{12, 0, static_cast<std::uint16_t>(2048), 0};
  bad.el_error = proto::HubAxisError::Parity;
  while (seconds() < 0.5) {
    station_.send_reading(bad);
    io.run_for(std::chrono::milliseconds(25));
    io.restart();
    backend->tick(seconds(), go, control::AzEl{});
    EXPECT_EQ(duty(0), 0U) << "driven while the elevation encoder has no position";
  }
  const auto faults = backend->faults();
  ASSERT_FALSE(faults.empty());
  std::string all;
  for (const auto& f : faults) all += f + " | ";
  EXPECT_NE(std::find(faults.begin(), faults.end(), "el encoder (EncoderHub): parity error"),
            faults.end())
      << all;
  EXPECT_FALSE(backend->position(seconds()).has_value());
  // Good frames again: the fault clears by itself (nothing was latched) and the antenna moves.
  bool driven = false;
  while (seconds() < 1.5 && !driven) {
    send_frame(180.0, 10.0);
    io.run_for(std::chrono::milliseconds(25));
    io.restart();
    backend->tick(seconds(), go, control::AzEl{});
    driven = duty(0) > 0;
  }
  EXPECT_TRUE(driven);
  std::string after;
  for (const auto& f : backend->faults()) after += f + " | ";
  EXPECT_TRUE(backend->faults().empty()) << after;
}

TEST_F(PwmBackendTest, AHubFrameWhoseBitsAreNotTheMountsIsAFaultNamingBoth) {
  boost::asio::io_context io;
  auto backend = make_pwm_backend(io, config(14));
  const auto start = Clock::now();
  const auto seconds = [&start] {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  control::Demand go;
  go.position = control::AzEl{200.0, 10.0};
  ASSERT_EQ(::write(station_.master(), "\0", 1), 1);
  const auto run = [&](double until_s) {
    while (seconds() < until_s) {
      send_frame(180.0, 10.0);
      io.run_for(std::chrono::milliseconds(25));
      io.restart();
      backend->tick(seconds(), go, control::AzEl{});
      EXPECT_EQ(duty(0), 0U) << "driven on angles read at the wrong resolution";
      EXPECT_EQ(duty(1), 0U);
    }
  };
  run(0.5);
  const auto faults = backend->faults();
  ASSERT_FALSE(faults.empty());
  EXPECT_NE(faults.back().find("12-bit frames but [mount.az] encoder_bits = 14"), std::string::npos)
      << faults.back();
  EXPECT_FALSE(backend->position(seconds()).has_value());
  backend->clear_faults();  // the jumpers were not changed: the next frame latches it again
  run(seconds() + 0.3);
  EXPECT_FALSE(backend->faults().empty());
}

// A limit switch edge turns the drive towards it off within 20 ms, between ticks.
TEST_F(PwmBackendTest, ALimitSwitchEdgeTurnsTheDriveTowardsItOffAtOnce) {
  boost::asio::io_context io;
  DaemonConfig c = config();
  c.gpio.az_cw_limit = linux_os::GpioLineSpec{"gpiochip0", 6, false, "[gpio] az_cw_limit"};
  testing::FakeGpio gpio(io);
  const auto start = Clock::now();
  const auto seconds = [&start] {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  GuardedAntenna antenna(make_pwm_backend(io, c), c.gpio,
                         GuardParts{&gpio, nullptr, (station_.dir() / "estop.latched").string(),
                                    seconds, [] {}, [](const std::string&) {}});
  control::Demand go;
  go.position = control::AzEl{200.0, 10.0};
  ASSERT_EQ(::write(station_.master(), "\0", 1), 1);
  while (seconds() < 1.0 && duty(0) == 0) {
    send_frame(180.0, 10.0);
    io.run_for(std::chrono::milliseconds(50));
    io.restart();
    antenna.tick(seconds(), go, control::AzEl{});
  }
  ASSERT_GT(duty(0), 0U) << "the azimuth bridge was never driven clockwise";
  // The switch opens half-way between two ticks; no tick runs until the drive is seen off.
  send_frame(180.0, 10.0);
  io.run_for(std::chrono::milliseconds(25));
  io.restart();
  const auto edge = Clock::now();
  gpio.set_input("[gpio] az_cw_limit", true);
  while (duty(0) != 0 && Clock::now() - edge < std::chrono::milliseconds(200)) {
    io.run_for(std::chrono::milliseconds(1));
    io.restart();
  }
  const double off_ms = std::chrono::duration<double, std::milli>(Clock::now() - edge).count();
  std::printf("[ timing   ] drive off %.1f ms after the limit edge\n", off_ms);
  EXPECT_EQ(duty(0), 0U);
  EXPECT_LE(off_ms, 20.0);
  EXPECT_EQ(duty(1), 0U) << "the switch must not reverse the motor";
  antenna.tick(seconds(), go, control::AzEl{});
  EXPECT_EQ(duty(0), 0U) << "the next tick drove into the switch again";
}

// The IBT-2's enables on a GPIO line: high while driving, low after a stop.
TEST_F(PwmBackendTest, TheEnableLineFollowsTheDriveAndDropsOnAStop) {
  boost::asio::io_context io;
  DaemonConfig c = config();
  c.backend = BackendKind::Hardware;
  c.hardware.az.enable = linux_os::GpioLineSpec{"gpiochip0", 22, false, "[hardware.az] enable"};
  testing::FakeGpio gpio(io);
  HardwarePorts ports;
  ports.gpio = &gpio;
  auto backend = make_hardware_backend(io, c, ports);
  EXPECT_FALSE(gpio.outputs["[hardware.az] enable"]) << "enabled before anything was driven";
  control::Demand go;
  go.position = control::AzEl{200.0, 10.0};
  ASSERT_EQ(::write(station_.master(), "\0", 1), 1);
  for (int i = 0; i < 40 && duty(0) == 0; ++i) {
    send_frame(180.0, 10.0);
    io.run_for(std::chrono::milliseconds(20));
    io.restart();
    backend->tick(0.05 * i, go, control::AzEl{});
  }
  ASSERT_GT(duty(0), 0U);
  EXPECT_TRUE(gpio.outputs["[hardware.az] enable"]);
  backend->stop_now(2.0);
  EXPECT_EQ(duty(0), 0U);
  EXPECT_FALSE(gpio.outputs["[hardware.az] enable"]);
}

TEST_F(PwmBackendTest, AMissingChipOrHubIsAClearErrorAndNothingIsDriven) {
  boost::asio::io_context io;
  DaemonConfig c = config();
  c.pwm.az.chip_dir = (station_.dir() / "pwmchip9").string();
  c.pwm.el.chip_dir = c.pwm.az.chip_dir;
  try {
    (void)make_pwm_backend(io, c);
    FAIL() << "opened a missing PWM chip";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[pwm] azimuth"), std::string::npos) << e.what();
  }
  c = config();
  c.hub.device = (station_.dir() / "no-hub").string();
  try {
    (void)make_pwm_backend(io, c);
    FAIL() << "opened a missing hub";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[hub] device"), std::string::npos) << e.what();
  }
  EXPECT_EQ(duty(0) + duty(1) + duty(2) + duty(3), 0U);
}

}  // namespace
}  // namespace azt::app
