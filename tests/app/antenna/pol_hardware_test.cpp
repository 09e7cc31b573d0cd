// The `hardware` backend's polarisation axis ([hardware.pol], docs/hardware.md): relays on GPIO
// and a pot on an MCP3008, opened beside the azimuth and elevation devices of the hardware
// station, on simulated buses. The pol plant follows its relays; azimuth and elevation stand
// still (their demand holds). Time is virtual. The same feed counted by a reed on the fake GPIO
// (sensor = "pulses"): it homes at start, holds its feed angle until homed, then follows it by the
// count. And the configurations that cannot drive a pol axis, refused with the reason.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <span>
#include <string>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_devices.hpp"
#include "azt/sim/axis_plant.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "station/guarded_antenna.hpp"
#include "support/code_spi.hpp"
#include "support/fake_gpio.hpp"
#include "support/hardware_station.hpp"

namespace azt::app {
namespace {

constexpr const char* kPolAxis = R"(
[mount.pol]
max_rate_deg_s = 2.0
min_deg = -95.0
max_deg = 95.0
[sim.pol]
start_deg = -20.0
[hardware.pol]
drive = "relay"
relay_forward = 7
relay_reverse = 8
window_deg = 0.5
lsb_deg = 0.2
sensor = "mcp3008"
adc_device = "/dev/spidev0.2"
pot_calibration = [0, -95.0, 1023, 95.0]
)";

/// The rotator box of the elevation, ideal: the ADS1115 reads the angle of the wiper last sent.
class CodeI2c final : public linux_os::I2cBus {
 public:
  explicit CodeI2c(const double* el_deg) : el_deg_(el_deg) {}
  Result<bool> write(std::uint8_t /*addr*/, std::span<const std::uint8_t> bytes) override {
    if (!bytes.empty()) pointer_ = bytes[0];
    return true;
  }
  Result<bool> read(std::uint8_t /*addr*/, std::span<std::uint8_t> bytes) override {
    const int v =
        pointer_ == 0x01 ? 0x8000 : static_cast<int>(std::lround(*el_deg_ / 90.0 * 26000.0));
    bytes[0] = static_cast<std::uint8_t>((v >> 8) & 0xFF);
    bytes[1] = static_cast<std::uint8_t>(v & 0xFF);
    return true;
  }

 private:
  const double* el_deg_;
  std::uint8_t pointer_ = 0;
};

/// kPolAxis's feed counted by a reed: 2 counts a degree, the home switch closed below −90°.
constexpr double kPolCountsPerDeg = 2.0;
constexpr double kPolHomeDeg = -90.0;
std::string pulse_pol_axis() {
  std::string pol = kPolAxis;
  pol.erase(pol.find("sensor = \"mcp3008\""));
  pol.replace(pol.find("lsb_deg = 0.2"), 13, "lsb_deg = 0.5");  // the relay's step: one count
  return pol + R"(sensor = "pulses"
pulse_line = 14
home_switch = 15
counts_per_deg = 2.0
home_deg = -90.0
home_seek_duty = -1.0
)";
}

struct PolRig {
  explicit PolRig(const std::string& extra = kPolAxis)
      : config(daemon_config_from(
            ConfigFile::parse(std::string(testing::kHardwareStation) + extra, "hw.toml"))),
        pol(*config.sim.pol) {
    ports.gpio = &gpio;
    ports.epoch = epoch;
    gpio.preset("[hardware.pol] home_switch", pol.shaft_deg() < kPolHomeDeg);
    ports.open_spi = [this](const std::string& path,
                            std::uint32_t) -> Result<std::unique_ptr<linux_os::SpiBus>> {
      if (path == "/dev/spidev0.2") {
        return std::unique_ptr<linux_os::SpiBus>(std::make_unique<testing::CodeSpi>([this] {
          return static_cast<int>(std::lround((pol.shaft_deg() + 95.0) / 190.0 * 1023.0));
        }));
      }
      // The azimuth pot at 100° (0–450° on 1023 counts); the elevation box's wiper is written.
      return std::unique_ptr<linux_os::SpiBus>(std::make_unique<testing::CodeSpi>(
          [] { return 227; }, [this](int wiper) { el_deg = wiper / 255.0 * 180.0; }));
    };
    ports.open_i2c = [this](const std::string&) -> Result<std::unique_ptr<linux_os::I2cBus>> {
      return std::unique_ptr<linux_os::I2cBus>(std::make_unique<CodeI2c>(&el_deg));
    };
  }

  [[nodiscard]] bool relay(const char* key) const {
    const auto it = gpio.outputs.find(key);
    return it != gpio.outputs.end() && it->second;
  }
  void run(AntennaBackend& a, const control::PolDemand& demand, double seconds) {
    for (const double end = t + seconds; t < end; t += 0.05) {
      const bool fwd = relay("[hardware.pol] relay_forward");
      const bool rev = relay("[hardware.pol] relay_reverse");
      const double before = pol.shaft_deg();
      pol.step(fwd ? 1.0 : rev ? -1.0 : 0.0, 0.05);
      if (config.hardware.pol->pulses) count(before, t + 0.05);
      a.set_pol_demand(demand);
      a.tick(t, control::Demand{}, control::AzEl{});
    }
  }

  /// A counted feed's reed closes at every count crossed, its home switch changes at −90°: the
  /// edges stamped on the loop's clock, delivered by the loop.
  void count(double before_deg, double at_s) {
    const auto at = epoch + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(at_s));
    testing::turn_reed(gpio, "[hardware.pol]", before_deg, pol.shaft_deg(), kPolCountsPerDeg,
                       kPolHomeDeg, at);
    io.poll();
    io.restart();
  }
  [[nodiscard]] static control::AxisStatus pol_of(const AntennaBackend& a) {
    for (const NamedAxisStatus& axis : a.axes()) {
      if (axis.axis == "pol") return axis.status;
    }
    ADD_FAILURE() << "no pol axis in axes()";
    return {};
  }

  boost::asio::io_context io;
  DaemonConfig config;
  testing::FakeGpio gpio{io};
  HardwarePorts ports;
  std::chrono::steady_clock::time_point epoch = std::chrono::steady_clock::now();
  sim::AxisPlant pol;
  double el_deg = 10.0;
  double t = 0.0;
};

TEST(PolHardware, RelaysAndAPotTurnTheFeedToItsTarget) {
  PolRig rig;
  auto backend = make_hardware_backend(rig.io, rig.config, rig.ports);
  EXPECT_NE(backend->describe().find("pol: relays"), std::string::npos) << backend->describe();
  ASSERT_TRUE(backend->pol_status().has_value());
  rig.run(*backend, control::PolDemand{30.0, 0.0}, 40.0);
  EXPECT_NEAR(rig.pol.shaft_deg(), 30.0, 0.5 + 0.2 + 0.1);  // window + pot step + a tick's run
  const auto status = backend->pol_status();
  EXPECT_NEAR(status->mount_deg, 30.0, 1.0);
  ASSERT_TRUE(status->target_mount_deg.has_value());
  EXPECT_NEAR(*status->target_mount_deg, 30.0, 1e-9);
  EXPECT_FALSE(status->moving);
  EXPECT_DOUBLE_EQ(status->min_deg, -95.0);
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  // −80° and +100° are the same linear polarisation; +100° is beyond the travel.
  rig.run(*backend, control::PolDemand{-80.0, 0.0}, 70.0);
  EXPECT_NEAR(rig.pol.shaft_deg(), -80.0, 0.9);
  // Held (no feed angle): the relays open and stay open.
  rig.run(*backend, control::PolDemand{}, 1.0);
  EXPECT_FALSE(rig.relay("[hardware.pol] relay_forward"));
  EXPECT_FALSE(rig.relay("[hardware.pol] relay_reverse"));
}

TEST(PolHardware, StopNowStopsThePolAxisWithTheOthers) {
  PolRig rig;
  auto backend = make_hardware_backend(rig.io, rig.config, rig.ports);
  rig.run(*backend, control::PolDemand{60.0, 0.0}, 2.0);
  ASSERT_TRUE(rig.relay("[hardware.pol] relay_forward"));
  backend->stop_now(rig.t);
  EXPECT_FALSE(rig.relay("[hardware.pol] relay_forward"));
  rig.run(*backend, control::PolDemand{60.0, 0.0}, 1.0);
  EXPECT_FALSE(rig.relay("[hardware.pol] relay_forward")) << "moved while latched";
}

TEST(PolHardware, ACountedFeedHomesHoldsItsAngleThenFollowsItsCount) {
  PolRig rig(pulse_pol_axis());
  auto backend = make_hardware_backend(rig.io, rig.config, rig.ports);
  const std::string describe = backend->describe();
  EXPECT_NE(describe.find("pol: relays"), std::string::npos) << describe;
  EXPECT_NE(describe.find("home switch", describe.find("pol: ")), std::string::npos) << describe;
  rig.run(*backend, control::PolDemand{30.0, 0.0}, 1.0);
  // Homing first: the feed angle waits while the seek drives towards the switch at −90°.
  auto pol = PolRig::pol_of(*backend);
  EXPECT_EQ(pol.homing, control::HomingState::Seeking);
  EXPECT_NE(pol.held.find("not homed"), std::string::npos) << pol.held;
  EXPECT_TRUE(rig.relay("[hardware.pol] relay_reverse"));
  EXPECT_LT(rig.pol.shaft_deg(), -20.0);
  EXPECT_FALSE(backend->pol_status()->target_mount_deg.has_value()) << "held: no target shown";
  double homed_at_s = -1.0;
  for (int i = 0; i < 1200 && homed_at_s < 0.0; ++i) {
    rig.run(*backend, control::PolDemand{30.0, 0.0}, 0.1);
    if (PolRig::pol_of(*backend).homing == control::HomingState::Homed) homed_at_s = rig.t;
  }
  ASSERT_GT(homed_at_s, 0.0) << PolRig::pol_of(*backend).held;
  EXPECT_LT(homed_at_s, 80.0);
  rig.run(*backend, control::PolDemand{30.0, 0.0}, 80.0);
  pol = PolRig::pol_of(*backend);
  // The count's angle is the feed's within a count, the feed at its angle within the window.
  EXPECT_NEAR(pol.mount_deg, rig.pol.shaft_deg(), 1.0 / kPolCountsPerDeg + 0.01);
  EXPECT_NEAR(rig.pol.shaft_deg(), 30.0, 0.5 + 1.0 / kPolCountsPerDeg + 0.1);
  EXPECT_TRUE(pol.held.empty()) << pol.held;
  ASSERT_TRUE(pol.pulse_count.has_value());
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  // The operator homes it again; a STOP ends that homing and the feed holds, unreferenced.
  EXPECT_EQ(backend->home(rig.t, "pol"), std::nullopt);
  rig.run(*backend, control::PolDemand{30.0, 0.0}, 1.0);
  EXPECT_EQ(PolRig::pol_of(*backend).homing, control::HomingState::Seeking);
  backend->stop_homing(rig.t, "stopped by console");
  rig.run(*backend, control::PolDemand{30.0, 0.0}, 2.0);
  pol = PolRig::pol_of(*backend);
  EXPECT_EQ(pol.homing, control::HomingState::NotHomed);
  EXPECT_NE(pol.held.find("stopped by console"), std::string::npos) << pol.held;
  EXPECT_FALSE(rig.relay("[hardware.pol] relay_forward"));
  EXPECT_FALSE(rig.relay("[hardware.pol] relay_reverse"));
}

TEST(PolHardware, TheEStopEndsTheCountedFeedsHomingAndRefusesAnother) {
  PolRig rig(pulse_pol_axis() + "[gpio]\nestop = 20\n");
  const auto latch = std::filesystem::path(::testing::TempDir()) / "pol_pulses_estop.latched";
  std::filesystem::remove(latch);
  GuardedAntenna guarded(make_hardware_backend(rig.io, rig.config, rig.ports), rig.config.gpio,
                         GuardParts{&rig.gpio, nullptr, latch.string(), [&rig] { return rig.t; },
                                    [] {}, [](const std::string&) {}});
  rig.run(guarded, control::PolDemand{30.0, 0.0}, 1.0);
  ASSERT_EQ(PolRig::pol_of(guarded).homing, control::HomingState::Seeking);
  rig.gpio.set_input("[gpio] estop", true);
  rig.run(guarded, control::PolDemand{30.0, 0.0}, 0.5);
  EXPECT_EQ(PolRig::pol_of(guarded).homing, control::HomingState::NotHomed);
  EXPECT_FALSE(rig.relay("[hardware.pol] relay_reverse"));
  const auto refused = guarded.home(rig.t, "pol");
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->find("no homing now: the E-stop is latched"), std::string::npos) << *refused;
  std::filesystem::remove(latch);
}

TEST(PolHardware, AFeedReadByAPotHasNoCountToHome) {
  PolRig rig;
  auto backend = make_hardware_backend(rig.io, rig.config, rig.ports);
  EXPECT_EQ(backend->home(rig.t, "pol"), "this axis has no pulse sensor to home");
  EXPECT_NE(backend->home(rig.t, "feed")->find("only az, el and pol"), std::string::npos);
}

std::string refusal(const std::string& text) {
  try {
    (void)daemon_config_from(ConfigFile::parse(text, "pol.toml"));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(PolHardware, AnAxisThatCannotBeDrivenIsRefusedNotIgnored) {
  const std::string station = testing::kHardwareStation;
  std::string hub = kPolAxis;
  hub.replace(hub.find("sensor = \"mcp3008\""), 18, "sensor = \"hub\"");
  EXPECT_NE(refusal(station + hub).find("[hardware.pol].sensor must be"), std::string::npos)
      << refusal(station + hub);
  std::string none = kPolAxis;
  none.erase(none.find("sensor = \"mcp3008\""), 18);
  EXPECT_NE(refusal(station + none).find("EncoderHub reads azimuth and elevation only"),
            std::string::npos)
      << refusal(station + none);
  EXPECT_NE(refusal(station + "[mount.pol]\n").find("[hardware.pol]"), std::string::npos);
  std::string pwm = station;
  pwm.replace(pwm.find("backend = \"hardware\""), 20, "backend = \"pwm\"\n[hub]\ndevice = \"x\"");
  EXPECT_NE(refusal(pwm + "[mount.pol]\n").find("azimuth and elevation only"), std::string::npos);
  const std::string hamlib =
      "[station]\ngrid = \"FN06HE\"\n[target]\nname = \"stop\"\n[antenna]\nbackend = "
      "\"hamlib\"\n[hamlib]\nmodel = 1\n[mount.pol]\n";
  EXPECT_NE(refusal(hamlib).find("no polarisation axis"), std::string::npos) << refusal(hamlib);
  std::string no_mount = kPolAxis;
  no_mount.erase(0, no_mount.find("[hardware.pol]"));
  EXPECT_NE(refusal(station + no_mount).find("which the file does not have"), std::string::npos);
}

TEST(PolHardware, ThePwmBridgeOfThePolAxisHasChannelsOfItsOwn) {
  const std::string head = "[station]\ngrid = \"FN06HE\"\n[target]\nname = \"stop\"\n";
  const DaemonConfig c = daemon_config_from(
      ConfigFile::parse(head + "[pwm]\npol_rpwm = 6\npol_lpwm = 7\n", "pwm.toml"));
  EXPECT_EQ(c.pwm.of("pol").rpwm_channel, 6U);
  EXPECT_EQ(c.pwm.of("pol").lpwm_channel, 7U);
  EXPECT_EQ(c.pwm.of("el").rpwm_channel, 2U);
  EXPECT_NE(refusal(head + "[pwm]\npol_rpwm = 1\n").find("az_lpwm"), std::string::npos);
}

}  // namespace
}  // namespace azt::app
