// A pulse-counted azimuth on the `hardware` backend (docs/hardware.md, "Pulse sensors and
// homing"): relays turn a simulated rotator, whose reed closes on the fake GPIO every count and
// whose home switch is closed below 5°. The backend opens the lines as GpioPulseInput, the station
// homes at start, then tracks; a STOP ends a homing, and the operator's command starts another.
// Time is virtual: the edges carry the loop's clock, as the kernel's stamps do.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_devices.hpp"
#include "azt/sim/axis_plant.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "support/fake_gpio.hpp"
#include "support/hardware_station.hpp"

namespace azt::app {
namespace {

constexpr double kCountsPerDeg = 2.0;
constexpr double kHomeDeg = 5.0;

const std::string kPulseAzimuth = testing::kHardwareTop + R"([mount.az]
max_rate_deg_s = 3.0
[mount.el]
fixed_deg = 0.0
[sim.az]
start_deg = 40.0
[hardware.az]
drive = "relay"
relay_forward = 5
relay_reverse = 6
window_deg = 1.0
lsb_deg = 0.5
sensor = "pulses"
pulse_line = 12
home_switch = 13
counts_per_deg = 2.0
home_deg = 5.0
home_seek_duty = -1.0
)";

struct PulseRig {
  PulseRig() : config(daemon_config_from(ConfigFile::parse(kPulseAzimuth, "p.toml"))) {
    ports.gpio = &gpio;
    ports.epoch = epoch;
    plant.emplace(config.sim.az);
    gpio.preset("[hardware.az] home_switch", plant->shaft_deg() < kHomeDeg);
  }

  [[nodiscard]] bool relay(const char* key) const {
    const auto it = gpio.outputs.find(key);
    return it != gpio.outputs.end() && it->second;
  }
  /// The rotator follows its relays; each count crossed closes and opens the reed, and the home
  /// switch changes at 5°. The edges are stamped on the loop's clock and delivered by the loop.
  void step_plant(double dt) {
    const bool fwd = relay("[hardware.az] relay_forward");
    const bool rev = relay("[hardware.az] relay_reverse");
    const double before = plant->shaft_deg();
    plant->step(fwd ? 1.0 : rev ? -1.0 : 0.0, dt);
    const double after = plant->shaft_deg();
    const auto at = epoch + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(t + dt));
    testing::turn_reed(gpio, "[hardware.az]", before, after, kCountsPerDeg, kHomeDeg, at);
    io.poll();
    io.restart();
  }
  void run(AntennaBackend& a, const control::Demand& demand, double seconds) {
    const int ticks = static_cast<int>(std::lround(seconds / 0.05));
    for (int i = 0; i < ticks; ++i) {
      step_plant(0.05);
      t += 0.05;
      a.tick(t, demand, control::AzEl{});
    }
  }
  [[nodiscard]] static control::AxisStatus az_of(const AntennaBackend& a) {
    return a.axes().at(0).status;
  }

  boost::asio::io_context io;
  DaemonConfig config;
  testing::FakeGpio gpio{io};
  HardwarePorts ports;
  std::chrono::steady_clock::time_point epoch = std::chrono::steady_clock::now();
  std::optional<sim::AxisPlant> plant;
  double t = 0.0;
};

control::Demand point_at(double az_deg) {
  return control::Demand{control::AzEl{az_deg, 0.0}, "test", std::nullopt};
}

TEST(PulseHardware, TheAzimuthHomesOnItsSwitchAndThenTracksItsCount) {
  PulseRig rig;
  auto backend = make_hardware_backend(rig.io, rig.config, rig.ports);
  EXPECT_NE(backend->describe().find("home"), std::string::npos) << backend->describe();
  rig.run(*backend, point_at(100.0), 1.0);
  // Homing first: the target waits, the seek drives towards the switch at the low end.
  auto az = PulseRig::az_of(*backend);
  ASSERT_TRUE(az.homing.has_value());
  EXPECT_EQ(*az.homing, control::HomingState::Seeking);
  EXPECT_NE(az.held.find("not homed"), std::string::npos) << az.held;
  EXPECT_TRUE(rig.relay("[hardware.az] relay_reverse"));
  double homed_at_s = -1.0;
  for (int i = 0; i < 1200 && homed_at_s < 0.0; ++i) {
    rig.run(*backend, point_at(100.0), 0.1);
    if (PulseRig::az_of(*backend).homing == control::HomingState::Homed) homed_at_s = rig.t;
  }
  ASSERT_GT(homed_at_s, 0.0) << PulseRig::az_of(*backend).held;
  EXPECT_LT(homed_at_s, 60.0);
  rig.run(*backend, point_at(100.0), 60.0);
  az = PulseRig::az_of(*backend);
  // The count's angle is the shaft's within a count and the relay's window.
  EXPECT_NEAR(az.mount_deg, rig.plant->shaft_deg(), 1.0 / kCountsPerDeg + 0.01);
  EXPECT_NEAR(rig.plant->shaft_deg(), 100.0, 1.5);
  EXPECT_TRUE(az.held.empty()) << az.held;
  EXPECT_TRUE(backend->faults().empty());
}

TEST(PulseHardware, AStopEndsHomingAndTheOperatorStartsItAgain) {
  PulseRig rig;
  auto backend = make_hardware_backend(rig.io, rig.config, rig.ports);
  rig.run(*backend, point_at(100.0), 2.0);
  ASSERT_TRUE(rig.relay("[hardware.az] relay_reverse"));
  backend->stop_homing(rig.t, "stopped by console");
  rig.run(*backend, point_at(100.0), 0.1);
  auto az = PulseRig::az_of(*backend);
  EXPECT_EQ(az.homing, control::HomingState::NotHomed);
  EXPECT_NE(az.held.find("stopped by console"), std::string::npos) << az.held;
  EXPECT_FALSE(rig.relay("[hardware.az] relay_reverse"));
  EXPECT_FALSE(rig.relay("[hardware.az] relay_forward"));
  // Not homed: the target waits, nothing moves once the rotator has coasted to rest.
  rig.run(*backend, point_at(100.0), 3.0);
  const double stopped_deg = rig.plant->shaft_deg();
  rig.run(*backend, point_at(100.0), 5.0);
  EXPECT_NEAR(rig.plant->shaft_deg(), stopped_deg, 0.01);
  // The elevation is fixed and there is no feed: only the azimuth homes.
  EXPECT_TRUE(backend->home(rig.t, "el").has_value());
  EXPECT_TRUE(backend->home(rig.t, "pol").has_value());
  EXPECT_EQ(backend->home(rig.t, "az"), std::nullopt);
  rig.run(*backend, point_at(100.0), 1.0);
  EXPECT_EQ(PulseRig::az_of(*backend).homing, control::HomingState::Seeking);
}

}  // namespace
}  // namespace azt::app
