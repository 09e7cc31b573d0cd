// The motor temperature model (sim/motor_thermal_plant.hpp) alone, then read by the core's
// MotorTrips: a motor held at full duty against a stuck antenna heats past its limit, trips,
// stays latched while it cools, and is cleared by the operator only below the hysteresis.
#include "azt/sim/motor_thermal_plant.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "azt/control/motor_trips.hpp"

namespace azt::sim {
namespace {

constexpr double kTick = 0.1;

MotorThermalParams params() { return MotorThermalParams{20.0, 80.0, 300.0, 20.0}; }

control::MotorTrips trips() {
  control::MotorTripsConfig c;
  c.axis = "el";
  c.temperature_limit_c = 80.0;
  c.temperature_hysteresis_c = 5.0;
  return control::MotorTrips(control::MotorTripsConfig::make(c).value());
}

control::MotorReadings reading(double celsius) {
  return control::MotorReadings{std::nullopt, celsius, std::nullopt};
}

TEST(MotorThermalPlant, RisesWithDutySquaredAndCoolsToAmbient) {
  EXPECT_EQ((MotorThermalParams{20.0, -1.0, 300.0, 20.0}).validate().error().message,
            "rise_at_full_duty_c must not be negative");
  MotorThermalPlant m(params());
  EXPECT_DOUBLE_EQ(m.steady_c(0.5), 40.0);  // a quarter of the full-duty rise
  EXPECT_DOUBLE_EQ(m.steady_c(-1.0), 100.0);
  for (int i = 0; i < 3000; ++i) m.step(1.0, kTick);  // one time constant
  EXPECT_NEAR(m.temperature_c(), 100.0 - 80.0 * std::exp(-1.0), 1e-9);
  MotorThermalPlant coarse(params());
  coarse.step(1.0, 300.0);  // the same span in one step: exact discretisation
  EXPECT_NEAR(coarse.temperature_c(), m.temperature_c(), 1e-9);
  for (int i = 0; i < 30000; ++i) m.step(0.0, kTick);
  EXPECT_NEAR(m.temperature_c(), 20.0, 0.01);
}

TEST(MotorThermalTrip, HalfDutyNeverTrips) {
  MotorThermalPlant m(params());
  auto t = trips();
  for (int i = 0; i < 36000; ++i) {  // an hour at half duty settles at 40 °C
    m.step(0.5, kTick);
    ASSERT_TRUE(t.update(reading(m.temperature_c()), i * kTick));
  }
  EXPECT_NEAR(m.temperature_c(), 40.0, 0.1);
}

TEST(MotorThermalTrip, OverTemperatureTripsAndLatches) {
  MotorThermalPlant m(params());
  auto t = trips();
  int i = 0;
  double duty = 1.0;  // a stuck antenna: the motor held at full duty
  for (; i < 10000 && t.tripped() == control::MotorTrip::None; ++i) {
    m.step(duty, kTick);
    if (!t.update(reading(m.temperature_c()), i * kTick)) duty = 0.0;
  }
  ASSERT_EQ(t.tripped(), control::MotorTrip::Temperature);
  // 80 °C is reached at τ·ln(80/20) = 415.9 s.
  const double trip_s = i * kTick;
  EXPECT_NEAR(trip_s, 300.0 * std::log(4.0), 2 * kTick);
  EXPECT_EQ(t.reason().rfind("el: motor temperature 80.0 °C above 80 °C", 0), 0U) << t.reason();
  // Stopped, it cools; below the limit it stays latched, and the operator's reset is refused
  // until 75 °C (60/55 of the rise gone: τ·ln(60/55) = 26.1 s after the trip).
  for (; i * kTick < trip_s + 10.0; ++i) {
    m.step(duty, kTick);
    EXPECT_FALSE(t.update(reading(m.temperature_c()), i * kTick));
  }
  EXPECT_LT(m.temperature_c(), 80.0);
  EXPECT_GT(m.temperature_c(), 75.0);
  const auto refused = t.reset();
  ASSERT_TRUE(refused.has_value());
  EXPECT_EQ(refused->rfind("el: motor temperature 7", 0), 0U) << *refused;
  for (; i * kTick < trip_s + 30.0; ++i) {
    m.step(duty, kTick);
    EXPECT_FALSE(t.update(reading(m.temperature_c()), i * kTick));  // latched, though cool
  }
  EXPECT_LT(m.temperature_c(), 75.0);
  EXPECT_EQ(t.reset(), std::nullopt);
  EXPECT_TRUE(t.update(reading(m.temperature_c()), i * kTick));
}

}  // namespace
}  // namespace azt::sim
