// The `sim` backend flying a dish whose elevation is a pulse-counted linear actuator
// (examples/actuator_dish.toml; docs/hardware.md, "Linear actuators"): the configuration's
// [hardware.el] pulse keys become the simulated actuator and the station's count, the dish homes
// at start, tracks by its count, and a reed pulse lost on the way is found at the next pass of the
// home switch. Time is virtual: the backend's tick clock.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "antenna/antenna_backend.hpp"
#include "azt/sim/plant_rig.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {
namespace {

/// `text` with `from` replaced by `to` (a key of the example changed).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

DaemonConfig dish_config(const std::string& extra = "") {
  const std::string path = std::string(AZT_SOURCE_DIR) + "/examples/actuator_dish.toml";
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The home switch (5.83°) within the travel, so a stow passes it; a count off by one is lost.
  text = replaced(text, "el_min_deg = 6.0", "el_min_deg = 5.3");
  text = replaced(text, "home_tolerance_counts = 1", "home_tolerance_counts = 0");
  return daemon_config_from(ConfigFile::parse(text + extra, "dish.toml"));
}

struct DishRig {
  explicit DishRig(const std::string& extra = "")
      : config(dish_config(extra)), backend(make_sim_backend(config, &truth)) {}
  void run(double el_deg, double seconds) {
    const control::Demand demand{control::AzEl{180.0, el_deg}, "test", std::nullopt};
    const int ticks = static_cast<int>(std::lround(seconds / 0.05));
    for (int i = 0; i < ticks; ++i) {
      t += 0.05;
      backend->tick(t, demand, control::AzEl{});
    }
  }
  [[nodiscard]] control::AxisStatus el() const { return backend->axes().at(1).status; }
  [[nodiscard]] double true_el_deg() const { return truth->plants().el().shaft_deg(); }

  DaemonConfig config;
  std::shared_ptr<const sim::PlantRig> truth;
  std::unique_ptr<AntennaBackend> backend;
  double t = 0.0;
};

TEST(SimActuator, TheExampleIsAnActuatorDishCountedByItsReed) {
  const DaemonConfig c = dish_config();
  ASSERT_TRUE(c.sim.el_actuator.has_value());
  EXPECT_DOUBLE_EQ(c.sim.el_actuator->dish.pulses_per_mm, 1.0);
  EXPECT_DOUBLE_EQ(c.sim.el_actuator->dish.home_switch_mm, 525.0);
  // The dish starts at [sim.el] start_deg: 30° is 688.76 mm (the worked example).
  EXPECT_NEAR(c.sim.el_actuator->dish.start_mm, 688.76, 0.01);
}

TEST(SimActuator, TheDishHomesThenTracksByItsCount) {
  DishRig rig;
  rig.run(40.0, 1.0);
  EXPECT_EQ(rig.el().homing, control::HomingState::Seeking);
  EXPECT_LT(rig.true_el_deg(), 30.0) << "the seek drives towards the retracted end";
  double homed_at_s = -1.0;
  for (int i = 0; i < 1200 && homed_at_s < 0.0; ++i) {
    rig.run(40.0, 0.1);
    if (rig.el().homing == control::HomingState::Homed) homed_at_s = rig.t;
  }
  ASSERT_GT(homed_at_s, 0.0) << rig.el().held;
  EXPECT_LT(homed_at_s, 60.0);
  RecordProperty("homed_after_s", std::to_string(homed_at_s));
  rig.run(40.0, 60.0);
  // The count's angle is the dish's within a count at the coarse end, and the dish at the target
  // within the window plus a count.
  const double lsb_deg = 0.3086;
  EXPECT_NEAR(rig.el().mount_deg, rig.true_el_deg(), lsb_deg);
  EXPECT_NEAR(rig.true_el_deg(), 40.0, 0.2 + lsb_deg);
  EXPECT_TRUE(rig.backend->faults().empty());
}

TEST(SimActuator, ALostPulseIsFoundAtTheNextPassOfTheHomeSwitch) {
  for (const bool drop : {false, true}) {
    DishRig rig(drop ? "drop_pulse_at_s = 80.0\n" : "");
    rig.run(40.0, 120.0);  // homed, then up to 40° (the pulse lost on the way)
    ASSERT_EQ(rig.el().homing, control::HomingState::Homed) << rig.el().held;
    rig.run(5.4, 120.0);  // down through the home switch
    const auto faults = rig.backend->faults();
    if (drop) {
      EXPECT_EQ(rig.el().fault, control::FaultKind::PositionLost);
      ASSERT_FALSE(faults.empty());
      EXPECT_NE(faults.front().find("position lost"), std::string::npos) << faults.front();
    } else {
      EXPECT_TRUE(faults.empty()) << faults.front();
      EXPECT_NEAR(rig.true_el_deg(), 5.4, 0.2 + 0.3086);
    }
    EXPECT_LT(rig.true_el_deg(), 5.83) << "the dish passed the home switch";
  }
}

}  // namespace
}  // namespace azt::app
