// A stepper on the `hardware` backend (docs/hardware.md, "Steppers"): azimuth on a step/dir driver
// whose STEP is a sysfs PWM channel (a directory laid out like /sys/class/pwm/pwmchipN) and whose
// DIR is a GPIO line, read by a pot on an MCP3008; elevation on a second one. The plant turns by
// the pulses the channel is set to make; time is virtual (the backend's tick clock).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_devices.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "support/fake_gpio.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;

// A 1.8° motor at 8 microsteps through a 1:90 worm: 200 × 8 × 90 / 360 steps per degree.
constexpr double kStepsPerDeg = 400.0;

/// An MCP3008 answering with a pot on `angle_deg` (0…450° over 10 bits).
class PotAdc final : public linux_os::SpiBus {
 public:
  explicit PotAdc(const double& angle_deg) : angle_deg_(angle_deg) {}
  Result<bool> transfer(std::span<const std::uint8_t> /*tx*/, std::span<std::uint8_t> rx) override {
    const auto code = static_cast<unsigned>(std::lround(angle_deg_ / 450.0 * 1023.0));
    rx[0] = 0;
    rx[1] = static_cast<std::uint8_t>((code >> 8) & 0x3U);
    rx[2] = static_cast<std::uint8_t>(code & 0xFFU);
    return true;
  }

 private:
  const double& angle_deg_;
};

std::string station(const fs::path& chip) {
  const std::string axis = "drive = \"stepdir\"\nstep_chip = \"" + chip.string() +
                           "\"\nmax_step_hz = 1200.0\nstart_step_hz = 100.0\n"
                           "step_accel_hz_s = 2400.0\nsensor = \"mcp3008\"\n"
                           "pot_calibration = [0, 0.0, 1023, 450.0]\n";
  return "[station]\ngrid = \"FN06HE\"\n[target]\nname = \"stop\"\n[antenna]\nbackend = "
         "\"hardware\"\n[mount.az]\nmax_rate_deg_s = 3.0\n[mount.el]\nmax_rate_deg_s = 3.0\n"
         "[hardware.az]\n" +
         axis +
         "step_channel = 0\ndir = 17\nenable = 27\nadc_device = \"/dev/spidev0.1\"\n"
         "[hardware.el]\n" +
         axis + "step_channel = 1\ndir = 22\nadc_device = \"/dev/spidev0.0\"\n";
}

struct Mast {
  Mast()
      : chip(fs::temp_directory_path() /
             ("azt_stepchip_" + std::to_string(::getpid()) + "_" + std::to_string(count++))),
        config(daemon_config_from(ConfigFile::parse(station(chip), "s.toml"))) {
    make_chip(chip);
    ports.gpio = &gpio;
    ports.open_spi = [this](const std::string& path,
                            std::uint32_t) -> Result<std::unique_ptr<linux_os::SpiBus>> {
      return std::unique_ptr<linux_os::SpiBus>(
          std::make_unique<PotAdc>(path == "/dev/spidev0.1" ? az_deg : el_deg));
    };
  }
  ~Mast() { fs::remove_all(chip); }
  Mast(const Mast&) = delete;
  Mast& operator=(const Mast&) = delete;
  Mast(Mast&&) = delete;
  Mast& operator=(Mast&&) = delete;

  static void make_chip(const fs::path& dir) {
    fs::remove_all(dir);
    for (const char* channel : {"pwm0", "pwm1"}) {
      fs::create_directories(dir / channel);
      for (const char* f : {"period", "duty_cycle", "enable"})
        std::ofstream(dir / channel / f) << 0;
    }
    std::ofstream(dir / "export") << "";
  }
  [[nodiscard]] double attr(const char* channel, const char* name) const {
    double v = 0.0;
    std::ifstream(chip / channel / name) >> v;
    return v;
  }
  /// The pulse rate the channel makes now (none while the duty is zero or it is disabled).
  [[nodiscard]] double step_hz(const char* channel) const {
    if (attr(channel, "enable") == 0.0 || attr(channel, "duty_cycle") == 0.0) return 0.0;
    return 1e9 / attr(channel, "period");
  }
  [[nodiscard]] bool line(const char* key) const {
    const auto it = gpio.outputs.find(key);
    return it != gpio.outputs.end() && it->second;
  }
  void run(AntennaBackend& a, const control::Demand& demand, double seconds) {
    for (const double end = t + seconds; t < end; t += 0.05) {
      const double az_hz = step_hz("pwm0");
      const bool az_cw = line("[hardware.az] dir");
      // DIR turning while pulses run would put a step the wrong way.
      if (az_hz > 0.0 && az_cw != last_az_cw) dir_turned_under_pulses = true;
      last_az_cw = az_cw;
      az_deg += (az_cw ? 1.0 : -1.0) * az_hz / kStepsPerDeg * 0.05;
      el_deg += (line("[hardware.el] dir") ? 1.0 : -1.0) * step_hz("pwm1") / kStepsPerDeg * 0.05;
      a.tick(t, demand, control::AzEl{});
    }
  }

  static inline int count = 0;  ///< each mast its own chip directory
  fs::path chip;
  boost::asio::io_context io;
  testing::FakeGpio gpio{io};
  DaemonConfig config;
  HardwarePorts ports;
  double az_deg = 100.0;
  double el_deg = 10.0;
  double t = 0.0;
  bool last_az_cw = false;
  bool dir_turned_under_pulses = false;
};

TEST(StepDirBackend, SteppersReachTheTargetBothWaysClosedOnTheirPots) {
  Mast mast;
  auto backend = make_hardware_backend(mast.io, mast.config, mast.ports);
  EXPECT_NE(backend->describe().find("step/dir"), std::string::npos) << backend->describe();
  control::Demand go;
  go.position = control::AzEl{160.0, 40.0};
  mast.run(*backend, go, 40.0);
  const double pot_step_deg = 450.0 / 1023.0;
  EXPECT_NEAR(mast.az_deg, 160.0, 2.0 * pot_step_deg);
  EXPECT_NEAR(mast.el_deg, 40.0, 2.0 * pot_step_deg);
  EXPECT_TRUE(mast.line("[hardware.az] enable"));
  go.position = control::AzEl{120.0, 20.0};  // and back the other way
  mast.run(*backend, go, 40.0);
  EXPECT_NEAR(mast.az_deg, 120.0, 2.0 * pot_step_deg);
  EXPECT_NEAR(mast.el_deg, 20.0, 2.0 * pot_step_deg);
  EXPECT_FALSE(mast.dir_turned_under_pulses);
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  backend->stop_now(mast.t);
  EXPECT_EQ(mast.step_hz("pwm0"), 0.0);
  EXPECT_FALSE(mast.line("[hardware.az] enable"));
}

TEST(StepDirBackend, AMissingChannelOrDirLineNamesItsKeyAndNothingSteps) {
  Mast mast;
  mast.config.hardware.el.step_chip = (mast.chip / "no-such-chip").string();
  try {
    (void)make_hardware_backend(mast.io, mast.config, mast.ports);
    FAIL() << "opened without a STEP channel";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[hardware.el] step_channel"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(mast.step_hz("pwm0"), 0.0);
  EXPECT_FALSE(mast.line("[hardware.az] enable"));
  Mast busy;
  busy.gpio.make_busy(22);
  try {
    (void)make_hardware_backend(busy.io, busy.config, busy.ports);
    FAIL() << "opened with a busy DIR line";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[hardware.el] dir"), std::string::npos) << e.what();
  }
  EXPECT_EQ(busy.attr("pwm1", "enable"), 0.0);
}

}  // namespace
}  // namespace azt::app
