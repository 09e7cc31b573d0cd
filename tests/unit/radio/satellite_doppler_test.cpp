// Satellite Doppler for the rig: the passband relation against Gpredict's edge form, the step
// scaling, and the planner's update rule and "track the knob", with the rig frequencies from the
// exact classical closed forms (heard f/(1 + ṙ/c), sent f/(1 − ṙ/c), c = 299792.458 km/s; the
// formulas themselves are tests/unit/orbit/link_doppler_test.cpp's).
#include "azt/radio/satellite_doppler.hpp"

#include <gtest/gtest.h>

#include <optional>

#include "azt/radio/satellite_doppler_planner.hpp"

namespace azt::radio {
namespace {

constexpr double kC = 299792.458;  // km/s

TEST(SatelliteDoppler, PassbandRelationAsGpredictWritesItWithEdges) {
  // An inverting transponder, downlink 145.925-145.975 MHz, uplink 432.125-432.175 MHz, given by
  // its centres. Gpredict (track_downlink): up = UP_HIGH − (down − DOWN_LOW).
  const SatelliteTransmitter inverting{145.950e6, 432.150e6, TransponderMode::LinearInverting};
  EXPECT_NEAR(*paired_uplink_hz(inverting, 145.960e6), 432.175e6 - (145.960e6 - 145.925e6), 1e-6);
  EXPECT_NEAR(*paired_uplink_hz(inverting, 145.925e6), 432.175e6, 1e-6);
  // Non-inverting: up = UP_LOW + (down − DOWN_LOW).
  const SatelliteTransmitter linear{145.950e6, 432.150e6, TransponderMode::Linear};
  EXPECT_NEAR(*paired_uplink_hz(linear, 145.960e6), 432.125e6 + (145.960e6 - 145.925e6), 1e-6);
  const SatelliteTransmitter fm{145.800e6, 437.800e6, TransponderMode::Fm};
  EXPECT_EQ(paired_uplink_hz(fm, 145.810e6), 437.800e6);
  const SatelliteTransmitter beacon{145.800e6, std::nullopt, TransponderMode::Linear};
  EXPECT_EQ(paired_uplink_hz(beacon, 145.810e6), std::nullopt);
}

TEST(SatelliteDoppler, StepsScaleWithFrequencyFromTheirValueAt435MHz) {
  EXPECT_DOUBLE_EQ(scaled_step_hz(10.0, 435e6), 10.0);
  EXPECT_NEAR(scaled_step_hz(10.0, 145e6), 10.0 / 3.0, 1e-9);
  EXPECT_NEAR(scaled_step_hz(10.0, 2400e6), 10.0 * 2400.0 / 435.0, 1e-9);
  EXPECT_EQ(scaled_step_hz(10.0, 28e6), 1.0);  // 0.64 Hz: rigctld takes whole Hz
}

SatelliteRigPlan write_both(SatelliteDopplerPlanner& planner, double now_s, double rate) {
  const SatelliteRigPlan plan = planner.plan(now_s, rate, std::nullopt);
  planner.rx_written(now_s, plan.rx_hz);
  if (plan.tx_hz) planner.tx_written(now_s, *plan.tx_hz);
  return plan;
}

TEST(SatelliteDopplerPlanner, FmWritesTheCorrectedChannelAndIgnoresTheDial) {
  SatelliteDopplerPlanner planner({145.8e6, 437.8e6, TransponderMode::Fm});
  const SatelliteRigPlan first = planner.plan(0.0, -7.0, 145.8e6);
  EXPECT_TRUE(first.write_rx);
  EXPECT_TRUE(first.write_tx);
  EXPECT_FALSE(first.knob_moved);
  EXPECT_NEAR(first.rx_hz, 145.8e6 / (1.0 - 7.0 / kC), 1e-6);
  EXPECT_NEAR(*first.tx_hz, 437.8e6 / (1.0 + 7.0 / kC), 1e-6);
  planner.rx_written(0.0, first.rx_hz);
  planner.tx_written(0.0, *first.tx_hz);
  const SatelliteRigPlan turned = planner.plan(0.5, -7.0, 145.81e6);
  EXPECT_FALSE(turned.knob_moved);
  EXPECT_EQ(turned.satellite_downlink_hz, 145.8e6);
}

TEST(SatelliteDopplerPlanner, AStepOrASecondDecidesWhenToWrite) {
  SatelliteDopplerPlanner planner({435e6, std::nullopt, TransponderMode::Fm});
  write_both(planner, 0.0, 0.0);
  // 5 Hz of Doppler at 435 MHz: ṙ = −5 · c / 435e6 km/s. Under the 10 Hz step: wait for the second.
  const double five_hz_rate = -5.0 * kC / 435e6;
  EXPECT_FALSE(planner.plan(0.5, five_hz_rate, std::nullopt).write_rx);
  EXPECT_TRUE(planner.plan(1.0, five_hz_rate, std::nullopt).write_rx);
  // 11 Hz: over the step, at once.
  EXPECT_TRUE(planner.plan(0.1, -11.0 * kC / 435e6, std::nullopt).write_rx);
  // Under 1 Hz: never.
  EXPECT_FALSE(planner.plan(60.0, -0.5 * kC / 435e6, std::nullopt).write_rx);
}

/// An inverting transponder, the operator at the nominal pair; a pass at ṙ = 3 km/s; the dial
/// turned down by 10 kHz from the written RX. Returns the plan of the cycle that reads the dial.
SatelliteRigPlan turn_the_dial(SatelliteDopplerPlanner& planner) {
  const SatelliteRigPlan first = write_both(planner, 0.0, 3.0);
  EXPECT_EQ(first.satellite_downlink_hz, 435.1e6);
  return planner.plan(1.0, 3.0, first.rx_hz - 10000.0);
}

TEST(SatelliteDopplerPlanner, TrackTheKnobOnAnInvertingTransponder) {
  SatelliteDopplerPlanner planner({435.1e6, 145.9e6, TransponderMode::LinearInverting});
  const SatelliteRigPlan plan = turn_the_dial(planner);
  EXPECT_TRUE(plan.knob_moved);
  EXPECT_FALSE(plan.write_rx);  // the rig is where the operator put it
  EXPECT_TRUE(plan.write_tx);
  // Dial = 435.1e6 / (1 + 3/c) − 10000; satellite frame = dial · (1 + 3/c)
  // = 435.1e6 − 10000 · (1 + 3/c).
  const double sat_down = 435.1e6 - 10000.0 * (1.0 + 3.0 / kC);
  EXPECT_NEAR(plan.satellite_downlink_hz, sat_down, 1e-4);
  // Inverting: the uplink rises by what the downlink fell.
  EXPECT_NEAR(*plan.satellite_uplink_hz, 145.9e6 + (435.1e6 - sat_down), 1e-4);
  EXPECT_NEAR(*plan.tx_hz, (145.9e6 + (435.1e6 - sat_down)) / (1.0 - 3.0 / kC), 1e-4);
  EXPECT_GT(*plan.tx_hz, 145.9e6 / (1.0 - 3.0 / kC) + 9999.0);
}

TEST(SatelliteDopplerPlanner, TrackTheKnobOnANonInvertingTransponder) {
  SatelliteDopplerPlanner planner({435.1e6, 145.9e6, TransponderMode::Linear});
  const SatelliteRigPlan plan = turn_the_dial(planner);
  EXPECT_TRUE(plan.knob_moved);
  const double sat_down = 435.1e6 - 10000.0 * (1.0 + 3.0 / kC);
  EXPECT_NEAR(*plan.satellite_uplink_hz, 145.9e6 - (435.1e6 - sat_down), 1e-4);
  EXPECT_LT(*plan.tx_hz, 145.9e6 / (1.0 - 3.0 / kC) - 9999.0);
}

TEST(SatelliteDopplerPlanner, AfterTheKnobTheNewPlaceIsKeptAndCorrected) {
  SatelliteDopplerPlanner planner({435.1e6, 145.9e6, TransponderMode::LinearInverting});
  const SatelliteRigPlan turned = turn_the_dial(planner);
  planner.tx_written(1.0, *turned.tx_hz);
  const double dial = 435.1e6 / (1.0 + 3.0 / kC) - 10000.0;
  // The dial still reads where the operator left it: no new knob movement, nothing to write.
  const SatelliteRigPlan still = planner.plan(1.5, 3.0, dial);
  EXPECT_FALSE(still.knob_moved);
  EXPECT_FALSE(still.write_rx);
  // The pass goes on (ṙ = 2 km/s): the RX follows the new place.
  const SatelliteRigPlan later = planner.plan(3.0, 2.0, dial);
  EXPECT_FALSE(later.knob_moved);
  EXPECT_TRUE(later.write_rx);
  EXPECT_NEAR(later.rx_hz, turned.satellite_downlink_hz / (1.0 + 2.0 / kC), 1e-4);
}

TEST(SatelliteDopplerPlanner, RigRoundingIsNotTheKnob) {
  SatelliteDopplerPlanner planner({435.1e6, 145.9e6, TransponderMode::Linear});
  const SatelliteRigPlan first = planner.plan(0.0, 3.0, std::nullopt);
  const double rounded = 10.0 * static_cast<double>(static_cast<long long>(first.rx_hz / 10.0));
  planner.rx_written(0.0, rounded);  // the rig's 10 Hz step, as read back
  EXPECT_FALSE(planner.plan(0.5, 3.0, rounded).knob_moved);
  EXPECT_TRUE(planner.plan(0.5, 3.0, rounded + 1.0).knob_moved);
}

TEST(SatelliteDopplerPlanner, ForgetWrittenWritesBothAndReadsNoKnob) {
  SatelliteDopplerPlanner planner({435.1e6, 145.9e6, TransponderMode::Linear});
  write_both(planner, 0.0, 3.0);
  planner.forget_written();
  const SatelliteRigPlan plan = planner.plan(0.2, 3.0, 400e6);
  EXPECT_FALSE(plan.knob_moved);
  EXPECT_TRUE(plan.write_rx);
  EXPECT_TRUE(plan.write_tx);
  EXPECT_EQ(plan.satellite_downlink_hz, 435.1e6);
}

}  // namespace
}  // namespace azt::radio
