// Motor current, temperature and driver-fault trips (control/motor_trips.hpp): latched with the
// reason, cleared only by the operator and only when the reading is back (with hysteresis for
// the temperature).
#include "azt/control/motor_trips.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace azt::control {
namespace {

constexpr double kTick = 0.05;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

MotorTrips trips() {
  MotorTripsConfig c;
  c.axis = "az";
  c.current_limit_a = 10.0;
  c.current_trip_s = 0.5;
  c.temperature_limit_c = 80.0;
  c.temperature_hysteresis_c = 5.0;
  return MotorTrips(MotorTripsConfig::make(c).value());
}

MotorReadings amps(double a) { return MotorReadings{a, std::nullopt, std::nullopt}; }
MotorReadings celsius(double c) { return MotorReadings{std::nullopt, c, std::nullopt}; }

TEST(CurrentSense, Ibt2ScaleFromTheDataSheet) {
  // BTS7960B: k_ILIS 8500 typical with R_IS = 1 kΩ, so 1 V on IS is 8.5 A.
  const auto s = CurrentSense::make(CurrentSense{}).value();
  EXPECT_DOUBLE_EQ(s.amps(1.0), 8.5);
  const auto with_offset = CurrentSense::make({8.5, 0.02}).value();
  EXPECT_DOUBLE_EQ(with_offset.amps(0.01), 0.0);  // never negative
  EXPECT_NEAR(with_offset.amps(1.02), 8.5, 1e-12);
  EXPECT_FALSE(CurrentSense::make({0.0, 0.0}).ok());
  EXPECT_EQ(CurrentSense::make({8.5, -1.0}).error().message, "offset_v must be 0 to 5 V");
}

TEST(MotorTripsConfig, ErrorsNameTheField) {
  EXPECT_TRUE(MotorTripsConfig::make(MotorTripsConfig{}).ok());
  MotorTripsConfig c;
  c.current_limit_a = -1.0;
  EXPECT_EQ(MotorTripsConfig::make(c).error().message,
            "current_limit_a must be above 0 and at most 200 A");
  c = MotorTripsConfig{};
  c.current_trip_s = 0.0;
  EXPECT_NE(MotorTripsConfig::make(c).error().message.find("current_trip_s"), std::string::npos);
  c = MotorTripsConfig{};
  c.temperature_limit_c = kNan;
  EXPECT_NE(MotorTripsConfig::make(c).error().message.find("temperature_limit_c"),
            std::string::npos);
  c = MotorTripsConfig{};
  c.axis.clear();
  EXPECT_EQ(MotorTripsConfig::make(c).error().message, "axis must be named");
}

TEST(MotorTrips, StartCurrentShorterThanTheTripTimeIsAllowed) {
  auto m = trips();
  int i = 0;
  for (; i < 9; ++i) EXPECT_TRUE(m.update(amps(25.0), i * kTick));  // 0.40 s
  for (; i < 100; ++i) EXPECT_TRUE(m.update(amps(4.0), i * kTick));
  EXPECT_EQ(m.tripped(), MotorTrip::None);
}

TEST(MotorTrips, OverCurrentForTheTripTimeLatchesWithTheReason) {
  auto m = trips();
  int i = 0;
  for (; i < 10; ++i) EXPECT_TRUE(m.update(amps(12.3), i * kTick));
  EXPECT_FALSE(m.update(amps(12.3), i * kTick));  // 0.5 s above the limit
  EXPECT_EQ(m.tripped(), MotorTrip::Current);
  EXPECT_EQ(m.reason(), "az: motor current 12.3 A above 10 A for 0.5 s");
  // Latched: the current falls (the motor stopped) and the trip stays until the reset.
  for (++i; i < 20; ++i) EXPECT_FALSE(m.update(amps(0.0), i * kTick));
  EXPECT_EQ(m.reset(), std::nullopt);
  EXPECT_TRUE(m.update(amps(0.0), i * kTick));
  EXPECT_EQ(m.reason(), "");
}

TEST(MotorTrips, ResetRefusedWhileTheCurrentIsStillHigh) {
  auto m = trips();
  for (int i = 0; i <= 10; ++i) m.update(amps(15.0), i * kTick);
  ASSERT_EQ(m.tripped(), MotorTrip::Current);
  EXPECT_EQ(m.reset(), "az: motor current 15.0 A is not below 10 A");
  EXPECT_EQ(m.tripped(), MotorTrip::Current);
}

TEST(MotorTrips, OverTemperatureTripsAndClearsOnlyBelowTheHysteresis) {
  auto m = trips();
  EXPECT_TRUE(m.update(celsius(79.9), 0.0));
  EXPECT_FALSE(m.update(celsius(83.2), 1.0));
  EXPECT_EQ(m.tripped(), MotorTrip::Temperature);
  EXPECT_EQ(m.reason(), "az: motor temperature 83.2 °C above 80 °C");
  EXPECT_FALSE(m.update(celsius(78.0), 60.0));  // below the limit, but not by enough
  EXPECT_EQ(m.reset(),
            "az: motor temperature 78.0 °C is not yet below 75 °C (the 80 °C limit less 5 °C)");
  EXPECT_FALSE(m.update(celsius(74.9), 300.0));  // cooled: still latched until the operator
  EXPECT_EQ(m.tripped(), MotorTrip::Temperature);
  EXPECT_EQ(m.reset(), std::nullopt);
  EXPECT_TRUE(m.update(celsius(74.9), 301.0));
}

TEST(MotorTrips, DriverFaultTripsAtOnce) {
  auto m = trips();
  EXPECT_FALSE(m.update(MotorReadings{std::nullopt, std::nullopt, true}, 0.0));
  EXPECT_EQ(m.reason(), "az: motor driver reports a fault");
  EXPECT_EQ(m.reset(), "az: the motor driver still reports a fault");
  m.update(MotorReadings{std::nullopt, std::nullopt, false}, 1.0);
  EXPECT_EQ(m.reset(), std::nullopt);
  EXPECT_EQ(to_string(MotorTrip::DriverFault), "motor driver fault");
}

TEST(MotorTrips, ReadingsThatAreNotNumbersTrip) {
  auto m = trips();
  EXPECT_FALSE(m.update(amps(kNan), 0.0));
  EXPECT_EQ(m.tripped(), MotorTrip::BadReading);
  EXPECT_EQ(m.reason(), "az: motor current reading is not a number");
  EXPECT_NE(m.reset(), std::nullopt);
  auto n = trips();
  EXPECT_FALSE(n.update(celsius(kNan), 0.0));
  EXPECT_EQ(n.reason(), "az: motor temperature reading is not a number");
  auto o = trips();
  EXPECT_FALSE(o.update(amps(1.0), kNan));
}

TEST(MotorTrips, InputsWithoutALimitAreIgnored) {
  MotorTrips m(MotorTripsConfig::make(MotorTripsConfig{}).value());  // no limits configured
  EXPECT_TRUE(m.update(MotorReadings{99.0, 150.0, std::nullopt}, 0.0));
  EXPECT_TRUE(m.update(MotorReadings{99.0, 150.0, std::nullopt}, 10.0));
  EXPECT_FALSE(m.last_current_a().has_value());
}

}  // namespace
}  // namespace azt::control
