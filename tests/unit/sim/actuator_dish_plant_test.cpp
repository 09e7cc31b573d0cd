// The simulated actuator dish (sim/actuator_dish_plant.hpp) on its own: reed pulses, the coast,
// the home switch's edges, the end stops and a dropped pulse. Flown by the core's pieces in
// actuator_dish_tracking_test.cpp.
#include "azt/sim/actuator_dish_plant.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

namespace azt::sim {
namespace {

constexpr double kTick = 0.02;           // a 50 Hz control loop
constexpr double kHomeSwitchMm = 522.0;  // between the reed's pulses at 521.5 and 522.5 mm

control::ActuatorGeometryConfig worked_example() {
  control::ActuatorGeometryConfig g;
  g.pivot_to_fixed_mm = 650.0;
  g.pivot_to_moving_mm = 400.0;
  g.offset_deg = 48.0;
  g.retracted_mm = 520.0;
  g.extended_mm = 977.2;
  return g;
}

ActuatorDishParams dish(double start_mm = 700.0) {
  ActuatorDishParams p;
  p.geometry = worked_example();
  p.speed_mm_s = 8.0;
  p.time_constant_s = 0.15;
  p.stiction_duty = 0.1;
  p.pulses_per_mm = 1.0;
  p.pulse_phase = 0.5;
  p.home_switch_mm = kHomeSwitchMm;
  p.start_mm = start_mm;
  return p;
}

TEST(ActuatorDishPlant, ValidatesItsParameters) {
  EXPECT_TRUE(dish().validate().ok());
  auto p = dish();
  p.pulses_per_mm = 0.0;
  EXPECT_EQ(p.validate().error().message, "pulses_per_mm must be in (0, 100]");
  p = dish();
  p.home_switch_mm = 400.0;
  EXPECT_EQ(p.validate().error().message, "home_switch_mm must be within the stroke");
  p = dish();
  p.geometry.retracted_mm = 100.0;
  EXPECT_NE(p.validate().error().message.find("retracted_mm"), std::string::npos);
  EXPECT_EQ(to_string(ActuatorEventKind::HomeClosed), "home switch closed");
}

TEST(ActuatorDishPlant, PulsesOnePerMillimetreBothWaysAndCoasts) {
  auto plant = ActuatorDishPlant::make(dish(600.2)).value();
  int pulses = 0;
  for (int i = 0; i < 250; ++i) {  // 5 s at full duty: about 40 mm
    for (const auto& e : plant.step(1.0, kTick)) pulses += e.kind == ActuatorEventKind::Pulse;
  }
  const double driven_to_mm = plant.length_mm();
  for (int i = 0; i < 100; ++i) {  // the coast after the duty drops
    for (const auto& e : plant.step(0.0, kTick)) pulses += e.kind == ActuatorEventKind::Pulse;
  }
  EXPECT_GT(plant.length_mm(), driven_to_mm + 1.0);  // 8 mm/s × τ 0.15 s = 1.2 mm of coast
  // Reed closures at 600.5, 601.5, … mm up to the final length, coast included.
  EXPECT_EQ(pulses, static_cast<int>(std::floor(plant.length_mm() - 0.5)) - 600 + 1);
  EXPECT_NEAR(plant.angle_deg(), plant.geometry().angle_deg(plant.length_mm()).value(), 1e-12);
  // Back down past the start: the same reed counts the other way (the counter gives the sign).
  int back = 0;
  while (plant.length_mm() > 590.0) {
    for (const auto& e : plant.step(-1.0, kTick)) back += e.kind == ActuatorEventKind::Pulse;
  }
  EXPECT_GT(back, pulses);
  EXPECT_EQ(plant.pulses_emitted(), static_cast<std::uint64_t>(pulses + back));
}

TEST(ActuatorDishPlant, HomeSwitchEdgesAreTimedAndOrderedWithThePulses) {
  auto plant = ActuatorDishPlant::make(dish(530.0)).value();
  std::optional<double> closed_at;
  double last_s = -1.0;
  while (!closed_at) {
    for (const auto& e : plant.step(-1.0, kTick)) {
      EXPECT_GE(e.at_s, last_s);
      last_s = e.at_s;
      if (e.kind == ActuatorEventKind::HomeClosed) closed_at = e.at_s;
    }
  }
  EXPECT_TRUE(plant.home_closed());
  EXPECT_LE(*closed_at, plant.now_s());
  EXPECT_GT(*closed_at, plant.now_s() - kTick);
  // Into the actuator's own end stop: it stops there, however long it is driven.
  for (int i = 0; i < 200; ++i) plant.step(-1.0, kTick);
  EXPECT_EQ(plant.length_mm(), 520.0);
  EXPECT_EQ(plant.rate_mm_s(), 0.0);
}

TEST(ActuatorDishPlant, DropsExactlyOnePulse) {
  auto plant = ActuatorDishPlant::make(dish(600.2)).value();
  plant.drop_pulse_after(1.0);
  int pulses = 0;
  for (int i = 0; i < 250; ++i) {
    for (const auto& e : plant.step(1.0, kTick)) pulses += e.kind == ActuatorEventKind::Pulse;
  }
  EXPECT_EQ(plant.pulses_dropped(), 1U);
  EXPECT_EQ(plant.pulses_emitted(), static_cast<std::uint64_t>(pulses));
}

}  // namespace
}  // namespace azt::sim
