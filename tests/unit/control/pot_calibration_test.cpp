// Potentiometer inputs against the worked examples of seed 002 (BX-24 interface: "0 - 5 V for
// 0 - 360 degrees azimuth, 0 - 1.25 V for 0 - 90 degrees elevation", 10-bit ADC, "360/1024 or
// 0.35 degree") and converter datasheets (MCP3208: code = 4096·Vin/Vref; ADS1115 at ±6.144 V:
// 187.5 µV per count).
#include "azt/control/pot_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace azt::control {
namespace {

constexpr double kTol = 1e-9;

TEST(AdcSpec, CountsFromVolts) {
  EXPECT_EQ(kAdcBx24.max_counts(), 1023);
  EXPECT_EQ(kAdcBx24.counts_from_volts(5.0), 1024.0);
  EXPECT_EQ(kAdcBx24.counts_from_volts(1.25), 256.0);
  EXPECT_EQ(kAdcMcp3208At5V.max_counts(), 4095);
  EXPECT_EQ(kAdcMcp3208At5V.counts_from_volts(2.5), 2048.0);
  EXPECT_EQ(kAdcAds1115Fsr6V144.max_counts(), 32767);
  EXPECT_NEAR(kAdcAds1115Fsr6V144.counts_from_volts(187.5e-6), 1.0, kTol);
  EXPECT_NEAR(kAdcAds1115Fsr6V144.counts_from_volts(5.0), 26666.6666667, 1e-6);
}

TEST(AdcSpec, Validates) {
  EXPECT_TRUE(AdcSpec::make(10, 5.0).ok());
  EXPECT_EQ(AdcSpec::make(24, 2.5)->max_counts(), 16777215);
  EXPECT_FALSE(AdcSpec::make(7, 5.0).ok());
  EXPECT_FALSE(AdcSpec::make(25, 5.0).ok());
  EXPECT_FALSE(AdcSpec::make(10, 0.0).ok());
  EXPECT_FALSE(AdcSpec::make(10, std::nan("")).ok());
}

TEST(PotCalibration, SeedAzimuthZeroToFiveVoltsIsZeroTo360) {
  const auto az = PotCalibration::from_volts(kAdcBx24, 0.0, 0.0, 5.0, 360.0);
  ASSERT_TRUE(az.ok());
  EXPECT_NEAR(az->to_deg(0), 0.0, kTol);
  EXPECT_NEAR(az->to_deg(512), 180.0, kTol);
  EXPECT_NEAR(az->to_deg(1), 0.3515625, kTol);       // the seed's "0.35 degree" per count
  EXPECT_NEAR(az->to_deg(1023), 359.6484375, kTol);  // the largest code, just below 5 V
  EXPECT_NEAR(az->to_counts(90.0), 256.0, kTol);
}

TEST(PotCalibration, SeedElevationZeroToOneQuarterVoltsIsZeroTo90) {
  const auto el = PotCalibration::from_volts(kAdcBx24, 0.0, 0.0, 1.25, 90.0);
  ASSERT_TRUE(el.ok());
  EXPECT_NEAR(el->to_deg(0), 0.0, kTol);
  EXPECT_NEAR(el->to_deg(128), 45.0, kTol);
  EXPECT_NEAR(el->to_deg(256), 90.0, kTol);
  EXPECT_NEAR(el->to_deg(3), 1.0546875, kTol);
}

TEST(PotCalibration, ReversedPot) {
  const auto p = PotCalibration::from_volts(kAdcBx24, 0.0, 360.0, 5.0, 0.0);
  ASSERT_TRUE(p.ok());
  EXPECT_NEAR(p->to_deg(256), 270.0, kTol);
  EXPECT_NEAR(p->to_counts(270.0), 256.0, kTol);
}

TEST(PotCalibration, OffsetTwoPoint) {
  // Points measured off the rails: 0.25 V at 10°, 4.75 V at 350° on a 12-bit 5 V MCP3208
  // (204.8 and 3891.2 counts): 2048 counts is the middle, 180°.
  const auto p = PotCalibration::from_volts(kAdcMcp3208At5V, 0.25, 10.0, 4.75, 350.0);
  ASSERT_TRUE(p.ok());
  EXPECT_NEAR(p->counts_a, 204.8, kTol);
  EXPECT_NEAR(p->to_deg(2048), 180.0, kTol);
  EXPECT_NEAR(p->to_deg(204.8), 10.0, kTol);
}

TEST(PotCalibration, GearedMultiTurnPots) {
  // Seed 002: a 3-turn pot on a 3:1 chain, 5 V across it: 0–5 V is 0–360°.
  const auto seed = PotCalibration::geared(kAdcBx24, 5.0, 3.0, 3.0, 0.0);
  ASSERT_TRUE(seed.ok());
  EXPECT_NEAR(seed->to_deg(512), 180.0, kTol);
  // A 10-turn pot turning 8 times per axis turn spans 450° (a 0–450° overlap rotator).
  const auto overlap = PotCalibration::geared(kAdcMcp3208At5V, 5.0, 10.0, 8.0, 0.0);
  ASSERT_TRUE(overlap.ok());
  EXPECT_NEAR(overlap->to_deg(4096), 450.0, kTol);
  EXPECT_NEAR(overlap->to_deg(2048), 225.0, kTol);
  EXPECT_NEAR(overlap->to_deg(1), 0.10986328125, kTol);
  // Centre-stop rotator: the wiper's 0 V end at −180°.
  const auto centred = PotCalibration::geared(kAdcMcp3208At5V, 5.0, 10.0, 8.0, -180.0);
  EXPECT_NEAR(centred->to_deg(4096), 270.0, kTol);
  EXPECT_FALSE(PotCalibration::geared(kAdcBx24, 5.0, 0.0, 3.0, 0.0).ok());
  EXPECT_FALSE(PotCalibration::geared(kAdcBx24, 5.0, 3.0, -3.0, 0.0).ok());
  EXPECT_FALSE(PotCalibration::geared(kAdcBx24, 0.0, 3.0, 3.0, 0.0).ok());
}

TEST(PotCalibration, RejectsDegeneratePoints) {
  EXPECT_FALSE(PotCalibration::make(100, 0, 100, 90).ok());
  EXPECT_FALSE(PotCalibration::make(0, 90, 256, 90).ok());
  EXPECT_FALSE(PotCalibration::make(0, 0, std::nan(""), 90).ok());
  EXPECT_FALSE(PotCalibration::make(0, 0, 256, std::numeric_limits<double>::infinity()).ok());
  EXPECT_FALSE(PotCalibration::from_volts(AdcSpec{10, 0.0}, 0, 0, 5, 360).ok());
}

TEST(MovingAverage, MeanOfTheLastWindow) {
  MovingAverage m(4);
  EXPECT_TRUE(std::isnan(m.mean()));
  m.push(1);
  m.push(2);
  EXPECT_EQ(m.mean(), 1.5);  // not yet full: the samples held
  m.push(100);
  m.push(101);
  EXPECT_EQ(m.mean(), 51.0);
  m.push(102);  // 1 leaves
  EXPECT_EQ(m.mean(), 76.25);
  EXPECT_EQ(m.count(), 4u);
  m.reset();
  EXPECT_EQ(m.count(), 0u);
  m.push(7);
  EXPECT_EQ(m.mean(), 7.0);
}

TEST(MovingAverage, WindowClampedAndExactOverLongRuns) {
  EXPECT_EQ(MovingAverage(0).window(), 1u);
  EXPECT_EQ(MovingAverage(1000).window(), 64u);
  MovingAverage m(64);
  // A million samples alternating 511 and 512, then a constant 600: the integer sum has no
  // residue, where a floating running sum would.
  for (int i = 0; i < 1000000; ++i) m.push(511 + (i % 2));
  EXPECT_EQ(m.mean(), 511.5);
  for (int i = 0; i < 64; ++i) m.push(600);
  EXPECT_EQ(m.mean(), 600.0);
}

PotInputConfig seed_elevation(std::size_t average) {
  PotInputConfig c;
  c.adc = kAdcBx24;
  c.calibration = *PotCalibration::from_volts(kAdcBx24, 0.0, 0.0, 1.25, 90.0);
  // 0–90° uses 0–256 counts: anything well above 90° (here 105.5°, 300 counts) is wiring.
  c.open_above_counts = 300;
  c.average_samples = average;
  return c;
}

TEST(PotInput, ShortToSupplyIsNotAnAngle) {
  const auto config = PotInputConfig::make(seed_elevation(1));
  ASSERT_TRUE(config.ok());
  PotInput pot(*config);
  EXPECT_NEAR(pot.push(128).deg, 45.0, kTol);
  const PotReading shorted = pot.push(1023);  // without the guard: 359.6°
  EXPECT_FALSE(shorted.ok());
  EXPECT_EQ(shorted.status, PotStatus::OpenHigh);
  EXPECT_TRUE(std::isnan(shorted.deg));
  EXPECT_TRUE(pot.push(300).ok());
  EXPECT_EQ(pot.push(301).status, PotStatus::OpenHigh);
}

TEST(PotInput, OpenWiperNearZeroWithGuard) {
  PotInputConfig c;
  c.adc = kAdcMcp3208At5V;
  c.calibration = *PotCalibration::from_volts(kAdcMcp3208At5V, 0.25, 0.0, 4.75, 360.0);
  c.open_below_counts = 100;   // 0.12 V: the pot never goes below 0.25 V
  c.open_above_counts = 3995;  // 4.88 V
  PotInput pot(*PotInputConfig::make(c));
  EXPECT_EQ(pot.push(0).status, PotStatus::OpenLow);  // pulled-down open wiper
  EXPECT_EQ(pot.push(99).status, PotStatus::OpenLow);
  EXPECT_TRUE(pot.push(100).ok());
  EXPECT_EQ(pot.push(4095).status, PotStatus::OpenHigh);
  EXPECT_NE(to_string(PotStatus::OpenLow).find("open"), std::string_view::npos);
}

TEST(PotInput, CountsBeyondTheConverterAreOutOfRange) {
  PotInput pot(*PotInputConfig::make(seed_elevation(1)));
  EXPECT_EQ(pot.push(-1).status, PotStatus::OutOfRange);
  PotInputConfig c = seed_elevation(1);
  c.open_above_counts.reset();
  PotInput unguarded(*PotInputConfig::make(c));
  EXPECT_TRUE(unguarded.push(1023).ok());
  EXPECT_EQ(unguarded.push(1024).status, PotStatus::OutOfRange);
  EXPECT_EQ(unguarded.push(std::numeric_limits<std::int32_t>::max()).status, PotStatus::OutOfRange);
}

TEST(PotInput, AveragesAndForgetsSamplesFromBeforeAFault) {
  PotInput pot(*PotInputConfig::make(seed_elevation(4)));
  pot.push(100);
  pot.push(102);
  pot.push(104);
  EXPECT_NEAR(pot.push(106).deg, 36.2109375, kTol);  // mean 103 counts
  EXPECT_NEAR(pot.push(108).deg, 36.9140625, kTol);  // mean 105 counts
  EXPECT_FALSE(pot.push(900).ok());
  // The first good sample after the fault stands alone: no mixing with the 100s.
  EXPECT_NEAR(pot.push(200).deg, 70.3125, kTol);
}

TEST(PotInputConfig, Validates) {
  PotInputConfig c = seed_elevation(1);
  EXPECT_TRUE(PotInputConfig::make(c).ok());
  c.open_below_counts = 300;  // equal to the upper guard: nothing valid left
  EXPECT_FALSE(PotInputConfig::make(c).ok());
  c = seed_elevation(1);
  c.open_above_counts = 1024;
  EXPECT_FALSE(PotInputConfig::make(c).ok());
  c = seed_elevation(0);
  EXPECT_FALSE(PotInputConfig::make(c).ok());
  c = seed_elevation(65);
  EXPECT_FALSE(PotInputConfig::make(c).ok());
  c = seed_elevation(64);
  EXPECT_TRUE(PotInputConfig::make(c).ok());
  c.calibration.counts_b = c.calibration.counts_a;
  EXPECT_FALSE(PotInputConfig::make(c).ok());
  c = seed_elevation(1);
  c.adc.bits = 30;
  EXPECT_FALSE(PotInputConfig::make(c).ok());
}

/// The worked example's actuator (docs/hardware.md "Linear actuators": 520 mm retracted, an
/// 18-inch stroke, a = 650 mm, b = 400 mm, θ0 = 48°) with a feedback pot on a 10-bit ADC reading
/// 100 counts retracted and 900 extended: 0.5715 mm a count.
PotInputConfig actuator_pot() {
  PotInputConfig c;
  c.adc = kAdcBx24;
  c.calibration = PotCalibration::make(100.0, 520.0, 900.0, 520.0 + 18 * 25.4).value();
  c.actuator = ActuatorGeometryConfig{
      650.0, 400.0, 48.0, 520.0, 520.0 + 18 * 25.4, ActuatorSense::ExtendRaises};
  return PotInputConfig::make(c).value();
}

TEST(PotInput, AnActuatorsPotReadsLengthThroughTheTriangle) {
  PotInput pot(actuator_pot());
  // The page's angles at the stroke's ends and middle (748.6 mm is 500 counts), to 0.01°.
  EXPECT_NEAR(pot.push(100).deg, 5.12, 0.01);
  EXPECT_NEAR(pot.push(500).deg, 39.56, 0.01);
  EXPECT_NEAR(pot.push(900).deg, 87.74, 0.01);
  // Equal steps of length are unequal steps of angle: the stroke's extended end is coarser.
  const double low_step = pot.push(101).deg - pot.push(100).deg;
  const double high_step = pot.push(900).deg - pot.push(899).deg;
  EXPECT_GT(high_step, 1.5 * low_step);
}

TEST(PotInput, AnActuatorsPotOutsideItsStrokeIsAFaultNotAnAngle) {
  PotInput pot(actuator_pot());
  const PotReading past = pot.push(950);  // 1005.8 mm: 28.6 mm past the extended end
  EXPECT_EQ(past.status, PotStatus::OutsideStroke);
  EXPECT_TRUE(std::isnan(past.deg));
  EXPECT_EQ(pot.push(20).status, PotStatus::OutsideStroke);  // 474.3 mm: short of retracted
}

TEST(PotInputConfig, AnActuatorsStepIsItsCoarsestCount) {
  // 0.5715 mm a count at the extended end's 0.3086°/mm (actuator_geometry_test.cpp).
  EXPECT_NEAR(actuator_pot().max_deg_per_count(), 0.5715 * 0.3086, 1e-4);
  EXPECT_NEAR(seed_elevation(1).max_deg_per_count(), 90.0 / 256.0, kTol);
  PotInputConfig c = actuator_pot();
  c.actuator->pivot_to_moving_mm = 100.0;  // the triangle cannot reach the stroke
  EXPECT_FALSE(PotInputConfig::make(c).ok());
}

}  // namespace
}  // namespace azt::control
