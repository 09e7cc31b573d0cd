// A dish's elevation on a linear actuator read by its feedback pot ([hardware.el]
// pot_calibration_mm with the actuator_* triangle, docs/hardware.md "Linear actuators"): relays
// on GPIO drive the simulated actuator (sim::ActuatorDishPlant, the worked example's 18-inch
// actuator), and an MCP3008 reads the pot's length. The `hardware` backend is the daemon's own;
// time is virtual.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_devices.hpp"
#include "azt/sim/actuator_dish_plant.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "support/code_spi.hpp"
#include "support/fake_gpio.hpp"
#include "support/hardware_station.hpp"

namespace azt::app {
namespace {

// The support's actuator pot (testing::kActuatorPotEl), with a 0.5° window and no averaging.
const std::string kActuatorEl = "[mount.el]\nmax_rate_deg_s = 2.0\n" + testing::kActuatorPotEl +
                                "window_deg = 0.5\naverage_samples = 1\n";

constexpr double kCoarsestCountDeg = 0.5715 * 0.3086;

sim::ActuatorDishParams worked_example_dish() {
  sim::ActuatorDishParams p;
  p.geometry = {650.0, 400.0, 48.0, 520.0, 977.2, control::ActuatorSense::ExtendRaises};
  p.speed_mm_s = 8.0;
  p.start_mm = 600.0;  // 16.67°
  return p;
}

struct ActuatorRig {
  ActuatorRig()
      : config(daemon_config_from(ConfigFile::parse(
            testing::kHardwareTop + testing::kHardwareAz + kActuatorEl, "hw.toml"))),
        dish(worked_example_dish()) {
    ports.gpio = &gpio;
    ports.open_spi = [this](const std::string& path,
                            std::uint32_t) -> Result<std::unique_ptr<linux_os::SpiBus>> {
      if (path == "/dev/spidev0.2") {
        return std::unique_ptr<linux_os::SpiBus>(
            std::make_unique<testing::CodeSpi>([this] { return pot_code(); }));
      }
      return std::unique_ptr<linux_os::SpiBus>(
          std::make_unique<testing::CodeSpi>([] { return 227; }));  // azimuth at 100°
    };
  }

  /// The pot's code for the actuator's length, or the code a test forces.
  [[nodiscard]] int pot_code() const {
    if (forced_code >= 0) return forced_code;
    return static_cast<int>(std::lround(100.0 + (dish.length_mm() - 520.0) / 457.2 * 800.0));
  }
  [[nodiscard]] bool relay(const char* key) const {
    const auto it = gpio.outputs.find(key);
    return it != gpio.outputs.end() && it->second;
  }
  void run(AntennaBackend& a, double el_deg, double seconds) {
    for (int i = 0; i < static_cast<int>(seconds / 0.05); ++i, t += 0.05) {
      const bool up = relay("[hardware.el] relay_forward");
      const bool down = relay("[hardware.el] relay_reverse");
      (void)dish.step(up ? 1.0 : down ? -1.0 : 0.0, 0.05);
      control::Demand demand;
      demand.position = control::AzEl{100.0, el_deg};
      a.tick(t, demand, control::AzEl{});
    }
  }

  boost::asio::io_context io;
  DaemonConfig config;
  testing::FakeGpio gpio{io};
  HardwarePorts ports;
  sim::ActuatorDishPlant dish;
  int forced_code = -1;
  double t = 0.0;
};

TEST(ActuatorPot, TheDishIsPointedByItsLengthThroughTheTriangle) {
  ActuatorRig rig;
  auto backend = make_hardware_backend(rig.io, rig.config, rig.ports);
  for (const double target_deg : {40.0, 80.0, 10.0}) {
    rig.run(*backend, target_deg, 60.0);
    // Within the window, one count at the coarse end, and the coast past a relay's opening.
    EXPECT_NEAR(rig.dish.angle_deg(), target_deg, 0.5 + kCoarsestCountDeg + 0.2) << target_deg;
    const auto here = backend->position(rig.t);
    ASSERT_TRUE(here.has_value());
    // The station's angle is the triangle's at the pot's length: within one count of the truth.
    EXPECT_NEAR(here->el_deg, rig.dish.angle_deg(), kCoarsestCountDeg) << target_deg;
    EXPECT_FALSE(here->moving);
  }
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
}

TEST(ActuatorPot, ALengthOutsideTheStrokeStopsTheAxisSayingSo) {
  ActuatorRig rig;
  auto backend = make_hardware_backend(rig.io, rig.config, rig.ports);
  rig.run(*backend, 60.0, 2.0);
  ASSERT_TRUE(rig.relay("[hardware.el] relay_forward"));
  rig.forced_code = 960;  // 1011 mm: 34 mm past the extended end, where no actuator can be
  rig.run(*backend, 60.0, 1.0);
  EXPECT_FALSE(rig.relay("[hardware.el] relay_forward"));
  ASSERT_FALSE(backend->faults().empty());
  EXPECT_NE(backend->faults().front().find("outside the actuator's stroke"), std::string::npos)
      << backend->faults().front();
}

}  // namespace
}  // namespace azt::app
