// The simulated axis against worked values: the reference plant of the control issue (az 1.5°/s,
// el 1.0°/s, τ 0.3 s, backlash 0.05°, stiction 0.1) and the encoder resolutions of the AnTrack-Pro
// manual's appendix (seed 000, "Encoder Resolution calculations": 12 bits, 1 count = 0.0879°).
// First-order values: 1 − e^−1 = 0.632121, 1 − e^−3 = 0.950213.
#include "azt/sim/axis_plant.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <string>

namespace azt::sim {
namespace {

constexpr double kTol = 1e-9;

AxisParams reference_az(double start_deg = 100.0) {
  AxisParams p;
  p.max_rate_deg_s = 1.5;
  p.time_constant_s = 0.3;
  p.backlash_deg = 0.05;
  p.stiction_duty = 0.1;
  p.encoder_bits = 12;
  p.start_deg = start_deg;
  p.min_deg = 0.0;
  p.max_deg = 360.0;
  return p;
}

AxisParams reference_el(double start_deg = 10.0) {
  AxisParams p = reference_az(start_deg);
  p.max_rate_deg_s = 1.0;
  p.min_deg = 0.0;
  p.max_deg = 90.0;
  return p;
}

void run(AxisPlant& plant, double duty, double seconds, double dt_s = 0.01) {
  const long steps = std::lround(seconds / dt_s);
  for (long k = 0; k < steps; ++k) plant.step(duty, dt_s);
}

TEST(AxisPlant, StepResponseReaches63PercentAtTau) {
  AxisPlant plant(reference_az());
  run(plant, 1.0, 0.3);
  EXPECT_NEAR(plant.motor_rate_deg_s(), 0.948180838, 1e-8);  // 1.5 × 0.632121
  run(plant, 1.0, 0.6);
  EXPECT_NEAR(plant.motor_rate_deg_s(), 1.425319397, 1e-8);  // 3τ: 1.5 × 0.950213
}

TEST(AxisPlant, PositionIsTheExactIntegralWhateverTheStep) {
  // Motor angle after 1 s at full duty from rest: 1.5 × (1 − 0.3 × (1 − e^(−1/0.3))) = 1.066053°
  // past the start; the shaft lags by half the play (the motor starts centred in it).
  for (const double dt : {1.0, 0.1, 0.01, 0.001}) {
    AxisPlant plant(reference_az(100.0));
    run(plant, 1.0, 1.0, dt);
    EXPECT_NEAR(plant.motor_deg(), 101.066053297, 1e-8) << "dt " << dt;
    EXPECT_NEAR(plant.shaft_deg(), 101.041053297, 1e-8) << "dt " << dt;
  }
}

TEST(AxisPlant, StableForStepsMuchLongerThanTau) {
  AxisPlant plant(reference_az(10.0));
  plant.step(1.0, 10.0);
  EXPECT_LE(plant.motor_rate_deg_s(), 1.5);
  EXPECT_NEAR(plant.motor_rate_deg_s(), 1.5, 1e-12);
  plant.step(0.0, 10.0);
  EXPECT_NEAR(plant.motor_rate_deg_s(), 0.0, 1e-12);
  EXPECT_GE(plant.motor_rate_deg_s(), 0.0);  // no overshoot into reverse
}

TEST(AxisPlant, MaxRateAndDutyMapping) {
  AxisPlant az(reference_az());
  run(az, 1.0, 10.0);
  EXPECT_NEAR(az.motor_rate_deg_s(), 1.5, kTol);
  run(az, 7.0, 1.0);  // clamped to full duty
  EXPECT_NEAR(az.motor_rate_deg_s(), 1.5, kTol);
  run(az, -1.0, 10.0);
  EXPECT_NEAR(az.motor_rate_deg_s(), -1.5, kTol);
  AxisPlant el(reference_el());
  run(el, 1.0, 10.0);
  EXPECT_NEAR(el.motor_rate_deg_s(), 1.0, kTol);
  run(el, 0.55, 10.0);  // (0.55 − 0.1)/(1 − 0.1) = half speed
  EXPECT_NEAR(el.motor_rate_deg_s(), 0.5, kTol);
  run(el, std::numeric_limits<double>::quiet_NaN(), 10.0);  // a NaN duty stops, never runs away
  EXPECT_NEAR(el.motor_rate_deg_s(), 0.0, kTol);
}

TEST(AxisPlant, DutyAtOrBelowStictionDoesNotMove) {
  for (const double duty : {0.05, 0.1, -0.1}) {
    AxisPlant plant(reference_az(100.0));
    run(plant, duty, 10.0);
    EXPECT_EQ(plant.motor_deg(), 100.0) << duty;
    EXPECT_EQ(plant.shaft_deg(), 100.0) << duty;
    EXPECT_EQ(plant.motor_rate_deg_s(), 0.0) << duty;
  }
}

TEST(AxisPlant, DutyAboveStictionMoves) {
  AxisPlant creep(reference_az(100.0));
  run(creep, 0.11, 10.0);
  EXPECT_NEAR(creep.motor_rate_deg_s(), 0.0166666667, 1e-9);  // 1.5 × 0.01/0.9
  EXPECT_GT(creep.shaft_deg(), 100.1);
  AxisPlant back(reference_az(100.0));
  run(back, -0.3, 10.0);
  EXPECT_NEAR(back.motor_rate_deg_s(), -0.3333333333, 1e-9);  // 1.5 × 0.2/0.9
  EXPECT_LT(back.shaft_deg(), 97.0);
}

TEST(AxisPlant, FirstMoveTakesUpHalfThePlay) {
  AxisPlant plant(reference_az(100.0));
  while (plant.motor_deg() < 100.0 + 0.025) {
    EXPECT_EQ(plant.shaft_deg(), 100.0);
    plant.step(0.3, 0.001);
  }
  plant.step(0.3, 0.001);
  EXPECT_GT(plant.shaft_deg(), 100.0);
}

TEST(AxisPlant, ReversalLosesTheBacklash) {
  AxisPlant plant(reference_az(100.0));
  run(plant, 0.5, 2.0, 0.001);
  // Reverse slowly (1/3 °/s) and find where the shaft starts back.
  double motor_peak = plant.motor_deg();
  double shaft_peak = plant.shaft_deg();
  double lost_deg = -1.0;
  for (int k = 0; k < 5000 && lost_deg < 0.0; ++k) {
    const double before = plant.shaft_deg();
    plant.step(-0.3, 0.001);
    motor_peak = std::max(motor_peak, plant.motor_deg());
    shaft_peak = std::max(shaft_peak, plant.shaft_deg());
    if (plant.shaft_deg() < before) lost_deg = motor_peak - plant.motor_deg();
  }
  // The motor crossed the whole play (0.05°) before the shaft turned; one step is 0.00033°.
  EXPECT_NEAR(lost_deg, 0.05, 0.0005);
  EXPECT_NEAR(shaft_peak, motor_peak - 0.025, 1e-12);
}

TEST(AxisPlant, NoBacklashShaftIsMotor) {
  AxisParams p = reference_az(100.0);
  p.backlash_deg = 0.0;
  AxisPlant plant(p);
  for (int k = 0; k < 300; ++k) {
    plant.step(k < 150 ? 0.8 : -0.8, 0.01);
    ASSERT_EQ(plant.shaft_deg(), plant.motor_deg());
  }
}

TEST(AxisPlant, EndStopsClampAndReport) {
  AxisPlant az(reference_az(359.0));
  EXPECT_FALSE(az.at_stop());
  run(az, 1.0, 5.0);
  EXPECT_EQ(az.shaft_deg(), 360.0);
  EXPECT_TRUE(az.at_stop());
  EXPECT_TRUE(az.at_max_stop());
  EXPECT_EQ(az.motor_rate_deg_s(), 0.0);
  EXPECT_NEAR(az.motor_deg(), 360.025, kTol);  // pressed against the shaft across the play
  EXPECT_EQ(az.encoder_raw(), 0);              // 360° is north again
  run(az, -1.0, 1.0);
  EXPECT_FALSE(az.at_stop());
  EXPECT_LT(az.shaft_deg(), 360.0);

  AxisPlant el(reference_el(1.0));
  run(el, -1.0, 5.0);
  EXPECT_EQ(el.shaft_deg(), 0.0);
  EXPECT_TRUE(el.at_min_stop());
  EXPECT_FALSE(el.at_max_stop());
  EXPECT_EQ(el.motor_rate_deg_s(), 0.0);

  AxisPlant parked(reference_el(0.0));
  EXPECT_TRUE(parked.at_min_stop());  // started on the stop
}

std::uint16_t raw_at(std::uint8_t bits, double deg) {
  AxisParams p = reference_az(deg);
  p.encoder_bits = bits;
  p.min_deg = -10.0;
  p.max_deg = 370.0;
  return AxisPlant(p).encoder_raw();
}

TEST(AxisPlant, EncoderQuantisation12Bits) {
  // Seed appendix: "encoder value of 1 gives … 0.0879 deg", "value of 2 … 0.1757 deg" (rounded
  // from 0.087890625 and 0.17578125: the reading changes exactly at those angles).
  EXPECT_EQ(AxisPlant(reference_az()).lsb_deg(), 0.087890625);
  EXPECT_EQ(raw_at(12, 0.0), 0);
  EXPECT_EQ(raw_at(12, 0.0878), 0);
  EXPECT_EQ(raw_at(12, 0.0879), 1);
  EXPECT_EQ(raw_at(12, 0.1757), 1);
  EXPECT_EQ(raw_at(12, 0.1758), 2);
  EXPECT_EQ(raw_at(12, 90.0), 1024);
  EXPECT_EQ(raw_at(12, 180.0), 2048);
  EXPECT_EQ(raw_at(12, 359.95), 4095);
  EXPECT_EQ(raw_at(12, 360.0), 0);
  EXPECT_EQ(raw_at(12, 365.0), 56);      // 5° past north on an overlap rotator
  EXPECT_EQ(raw_at(12, -0.05), 4095);    // just below the horizon
  EXPECT_EQ(raw_at(12, -0.0879), 4094);  // floor: a hair beyond −1 count
}

TEST(AxisPlant, EncoderQuantisation9And13And16Bits) {
  EXPECT_EQ(raw_at(9, 0.7), 0);  // 1 count = 0.703125°
  EXPECT_EQ(raw_at(9, 0.71), 1);
  EXPECT_EQ(raw_at(9, 359.3), 511);
  // Posital inclinometer, 13 bits: "(1 * (360.0/8192)) = 0.0439 deg".
  EXPECT_EQ(raw_at(13, 0.0439), 0);
  EXPECT_EQ(raw_at(13, 0.0440), 1);
  // 16 bits: 0.0054931640625° per count (the seed divides by 65535 and prints 0.00549).
  EXPECT_EQ(raw_at(16, 0.0054), 0);
  EXPECT_EQ(raw_at(16, 0.0055), 1);
  EXPECT_EQ(raw_at(16, 180.0), 32768);
  EXPECT_EQ(raw_at(16, 359.9999), 65535);
  AxisParams p = reference_az();
  p.encoder_bits = 16;
  EXPECT_EQ(AxisPlant(p).lsb_deg(), 0.0054931640625);
  EXPECT_EQ(AxisPlant(p).encoder_bits(), 16);
}

TEST(AxisPlantFaults, FrozenShaftHoldsWhileTheMotorRuns) {
  AxisPlant plant(reference_az(100.0));
  plant.inject({AxisFaultKind::FrozenShaft, 0});
  EXPECT_TRUE(plant.has_fault(AxisFaultKind::FrozenShaft));
  const std::uint16_t raw = plant.encoder_raw();
  run(plant, 1.0, 2.0);
  EXPECT_EQ(plant.shaft_deg(), 100.0);
  EXPECT_EQ(plant.encoder_raw(), raw);
  EXPECT_NEAR(plant.motor_rate_deg_s(), 1.5, 0.01);
  EXPECT_GT(plant.motor_deg(), 102.0);
  // Freed: the coupling grips where the shaft is (mid-play); no jump by the 2.5° the motor ran.
  // In 0.1 s at 1.5°/s the motor turns 0.15°, of which the half play takes 0.025°.
  plant.clear(AxisFaultKind::FrozenShaft);
  EXPECT_FALSE(plant.has_fault(AxisFaultKind::FrozenShaft));
  run(plant, 1.0, 0.1);
  EXPECT_NEAR(plant.shaft_deg(), 100.125, 1e-3);  // the motor was still 0.002°/s short of 1.5
}

TEST(AxisPlantFaults, ReversedMotorDrivesTheOtherWay) {
  AxisPlant plant(reference_az(100.0));
  plant.inject({AxisFaultKind::ReversedMotor, 0});
  run(plant, 1.0, 1.0);
  EXPECT_NEAR(plant.shaft_deg(), 98.958946703, 1e-8);  // the mirror of the step response
  EXPECT_LT(plant.motor_rate_deg_s(), 0.0);
  plant.clear_faults();
  EXPECT_FALSE(plant.has_fault(AxisFaultKind::ReversedMotor));
}

TEST(AxisPlantFaults, EncoderOffsetPersistsAndWraps) {
  AxisPlant plant(reference_az(90.0));
  EXPECT_EQ(plant.encoder_raw(), 1024);
  plant.inject({AxisFaultKind::EncoderOffset, 5});
  EXPECT_EQ(plant.encoder_raw(), 1029);
  run(plant, 0.0, 1.0);
  EXPECT_EQ(plant.encoder_raw(), 1029);
  plant.inject({AxisFaultKind::EncoderOffset, -1030});  // replaces, and wraps below zero
  EXPECT_EQ(plant.encoder_raw(), 4090);
  plant.clear(AxisFaultKind::EncoderOffset);
  EXPECT_EQ(plant.encoder_raw(), 1024);
}

TEST(AxisPlantFaults, EncoderGlitchLastsUntilTheNextStep) {
  AxisPlant plant(reference_az(90.0));
  plant.inject({AxisFaultKind::EncoderGlitch, 100});
  EXPECT_TRUE(plant.has_fault(AxisFaultKind::EncoderGlitch));
  EXPECT_EQ(plant.encoder_raw(), 1124);
  EXPECT_EQ(plant.encoder_raw(), 1124);
  plant.step(0.0, 0.01);
  EXPECT_EQ(plant.encoder_raw(), 1024);
  EXPECT_FALSE(plant.has_fault(AxisFaultKind::EncoderGlitch));
  EXPECT_EQ(to_string(AxisFaultKind::EncoderGlitch), "encoder glitch");
}

TEST(AxisPlant, IgnoresNonPositiveOrNonFiniteSteps) {
  AxisPlant plant(reference_az(100.0));
  plant.step(1.0, 0.0);
  plant.step(1.0, -1.0);
  plant.step(1.0, std::numeric_limits<double>::infinity());
  plant.step(1.0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(plant.motor_deg(), 100.0);
  EXPECT_EQ(plant.motor_rate_deg_s(), 0.0);
}

TEST(AxisParams, Validates) {
  EXPECT_TRUE(reference_az().validate().ok());
  EXPECT_TRUE(reference_el().validate().ok());
  EXPECT_TRUE(AxisParams{}.validate().ok());
  const auto broken = [](auto mutate) {
    AxisParams p = reference_az();
    mutate(p);
    return !p.validate().ok() && !AxisPlant::make(p).ok();
  };
  EXPECT_TRUE(broken([](AxisParams& p) { p.time_constant_s = 0.0; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.time_constant_s = std::nan(""); }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.max_rate_deg_s = -1.0; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.encoder_bits = 8; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.encoder_bits = 17; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.stiction_duty = 1.0; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.stiction_duty = -0.1; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.backlash_deg = -0.01; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.min_deg = 360.0; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.start_deg = 360.5; }));
  EXPECT_TRUE(broken([](AxisParams& p) { p.start_deg = -0.5; }));
  const auto message = [] {
    AxisParams p = reference_az();
    p.encoder_bits = 20;
    return p.validate().error().message;
  }();
  EXPECT_NE(message.find("encoder_bits"), std::string::npos);
}

TEST(AxisPlant, OneHourAt100HzIsCheap) {
  // The budget: an hour of virtual time at 100 Hz, per axis, well under 0.1 s of CPU.
  AxisPlant plant(reference_az(100.0));
  const std::clock_t start = std::clock();
  unsigned checksum = 0;
  for (int k = 0; k < 360000; ++k) {
    plant.step((k / 500) % 2 == 0 ? 0.8 : -0.8, 0.01);  // 5 s each way
    checksum += plant.encoder_raw();
  }
  const double cpu_s = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  RecordProperty("cpu_ms", std::to_string(cpu_s * 1000.0));
  EXPECT_LT(cpu_s, 0.1);
  EXPECT_GT(checksum, 0u);
  EXPECT_GT(plant.shaft_deg(), 90.0);  // back and forth, no drift out of the band
  EXPECT_LT(plant.shaft_deg(), 110.0);
}

}  // namespace
}  // namespace azt::sim
