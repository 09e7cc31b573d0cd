// The `sim` backend flying a dish whose elevation is a linear actuator (docs/hardware.md, "Linear
// actuators"). Counted by its reed (examples/actuator_dish.toml): the configuration's
// [hardware.el] pulse keys become the simulated actuator and the station's count, the dish homes
// at start, tracks by its count, and a reed pulse lost on the way is found at the next pass of the
// home switch. Read by its feedback pot (examples/actuator_dish_pot.toml): the daemon's PotInput
// reads the simulated length through the ADC's codes, and the dish tracks at once, unhomed.
// Time is virtual: the backend's tick clock.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <utility>

#include "antenna/antenna_backend.hpp"
#include "azt/sim/plant_rig.hpp"
#include "azt/sim/station_sim.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {
namespace {

/// `text` with `from` replaced by `to` (a key of the example changed).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

/// An example's text (`name` under examples/).
std::string example_text(const std::string& name) {
  std::ifstream in(std::string(AZT_SOURCE_DIR) + "/examples/" + name);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

DaemonConfig dish_config(const std::string& extra = "") {
  std::string text = example_text("actuator_dish.toml");
  // The home switch (5.83°) within the travel, so a stow passes it; a count off by one is lost.
  text = replaced(text, "el_min_deg = 6.0", "el_min_deg = 5.3");
  text = replaced(text, "home_tolerance_counts = 1", "home_tolerance_counts = 0");
  return daemon_config_from(ConfigFile::parse(text + extra, "dish.toml"));
}

/// The pot example, with `extra` appended to its last table ([sim.el]).
DaemonConfig pot_config(const std::string& extra = "") {
  return daemon_config_from(
      ConfigFile::parse(example_text("actuator_dish_pot.toml") + extra, "pot.toml"));
}

struct DishRig {
  explicit DishRig(DaemonConfig c)
      : config(std::move(c)), backend(make_sim_backend(config, &truth)) {}
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
  DishRig rig(dish_config());
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
    DishRig rig(dish_config(drop ? "drop_pulse_at_s = 80.0\n" : ""));
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

// The pot example's coarsest count: 0.5715 mm at the top of the stroke's 0.3086 °/mm.
constexpr double kPotCountDeg = 0.5715 * 0.3086;

TEST(SimActuator, ThePotExampleIsAnActuatorDishReadByItsPot) {
  const DaemonConfig c = pot_config();
  ASSERT_TRUE(c.sim.el_actuator.has_value());
  EXPECT_EQ(c.sim.el_actuator->reed(), nullptr);
  const control::PotInputConfig* pot = c.sim.el_actuator->pot();
  ASSERT_NE(pot, nullptr);
  ASSERT_TRUE(pot->actuator.has_value());
  EXPECT_DOUBLE_EQ(pot->actuator->extended_mm, 977.2);
  EXPECT_EQ(pot->adc.bits, 10);  // the MCP3008
  EXPECT_NEAR(c.sim.el_actuator->dish.start_mm, 688.76, 0.01);
  // The station's step on the axis is the pot's coarse count, as the hardware backend's.
  const auto control = sim::station_control_config(c.simulated());
  EXPECT_FALSE(control.el_drive.pulses.has_value());
  ASSERT_TRUE(control.el_drive.sensor_step_deg.has_value());
  EXPECT_NEAR(*control.el_drive.sensor_step_deg, kPotCountDeg, 0.002);
}

TEST(SimActuator, ThePotDishTracksAtOnceWithoutHoming) {
  DishRig rig(pot_config());
  // No reed: no homing, nothing held, the pot read from the first tick.
  rig.run(40.0, 1.0);
  EXPECT_FALSE(rig.el().homing.has_value());
  EXPECT_TRUE(rig.el().held.empty()) << rig.el().held;
  EXPECT_NEAR(rig.el().mount_deg, 30.0, 2.0) << "read where the dish stands, not assumed";
  for (const double target : {40.0, 80.0, 10.0}) {
    // 8 mm/s: 40° to 80° is about 200 mm; a minute leaves time to settle.
    rig.run(target, 60.0);
    // The pot's angle is the dish's within a count, and the dish at the target within the
    // window plus a count.
    EXPECT_NEAR(rig.el().mount_deg, rig.true_el_deg(), kPotCountDeg) << target;
    EXPECT_NEAR(rig.true_el_deg(), target, 0.2 + kPotCountDeg) << target;
    EXPECT_FALSE(rig.el().moving) << target;
  }
  const auto faults = rig.backend->faults();
  EXPECT_TRUE(faults.empty()) << faults.front();
  EXPECT_EQ(rig.el().fault, control::FaultKind::None) << rig.el().reason;
}

TEST(SimActuator, APotHasNoReedToLoseAPulseOf) {
  try {
    (void)pot_config("drop_pulse_at_s = 80.0\n");
    FAIL() << "drop_pulse_at_s was accepted with a pot";
  } catch (const UsageError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("[sim.el].drop_pulse_at_s"), std::string::npos) << what;
    EXPECT_NE(what.find("pot"), std::string::npos) << what;
  }
}

TEST(SimActuator, WithoutAStartTheDishStartsWithinItsStroke) {
  // No [sim.el] start_deg and no travel limit: the plant's 0° is below the retracted end (5.12°),
  // so the dish starts there, and a `hardware` file without [sim.el] still loads.
  const std::string text =
      replaced(example_text("actuator_dish_pot.toml"), "el_min_deg = 6.0", "el_min_deg = 0.0");
  const DaemonConfig c =
      daemon_config_from(ConfigFile::parse(replaced(text, "start_deg = 30.0", ""), "pot.toml"));
  ASSERT_TRUE(c.sim.el_actuator.has_value());
  EXPECT_NEAR(c.sim.el_actuator->dish.start_mm, 520.0, 1e-6);
  // Given outside the stroke, the start is an error naming it.
  try {
    (void)daemon_config_from(
        ConfigFile::parse(replaced(text, "start_deg = 30.0", "start_deg = 2.0"), "pot.toml"));
    FAIL() << "a start below the stroke was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[sim.el].start_deg"), std::string::npos) << e.what();
  }
}

TEST(SimActuator, APotInDegreesKeepsThePlainPlant) {
  std::string text = example_text("actuator_dish_pot.toml");
  text = replaced(text, "pot_calibration_mm = [100, 520.0, 900, 977.2]",
                  "pot_calibration = [100, 5.0, 900, 88.0]");
  for (const char* key : {"actuator_pivot_to_fixed_mm = 650.0",
                          "actuator_pivot_to_moving_mm = 400.0", "actuator_offset_deg = 48.0",
                          "actuator_retracted_mm = 520.0", "actuator_extended_mm = 977.2"}) {
    text = replaced(text, key, "");
  }
  text = replaced(text, "actuator_speed_mm_s = 8.0", "");
  const DaemonConfig c = daemon_config_from(ConfigFile::parse(text, "pot_deg.toml"));
  EXPECT_FALSE(c.sim.el_actuator.has_value());
}

}  // namespace
}  // namespace azt::app
