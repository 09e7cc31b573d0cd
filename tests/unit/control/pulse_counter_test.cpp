// Pulse counting (control/pulse_counter.hpp): a single reed or Hall channel counted in the
// drive's direction with K3NG's coast rule and a debounce, and quadrature decoded from its phase.
#include "azt/control/pulse_counter.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace azt::control {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

PulseCounter single(double min_spacing_s = 0.010) {
  PulseCounterConfig c;
  c.kind = PulseInputKind::SingleChannel;
  c.min_spacing_s = min_spacing_s;
  return PulseCounter(PulseCounterConfig::make(c).value());
}

PulseCounter quadrature(bool reversed = false) {
  PulseCounterConfig c;
  c.kind = PulseInputKind::Quadrature;
  c.reversed = reversed;
  return PulseCounter(PulseCounterConfig::make(c).value());
}

TEST(PulseCounterConfig, Validates) {
  EXPECT_TRUE(PulseCounterConfig::make(PulseCounterConfig{}).ok());
  PulseCounterConfig c;
  c.min_spacing_s = -0.001;
  const auto r = PulseCounterConfig::make(c);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "min_spacing_s must be 0 to 1 s");
  c.min_spacing_s = kNan;
  EXPECT_FALSE(PulseCounterConfig::make(c).ok());
  EXPECT_EQ(to_string(PulseInputKind::Quadrature), "quadrature");
  EXPECT_EQ(to_string(PulseInputKind::SingleChannel), "single channel");
}

TEST(PulseCounter, SingleChannelCountsInTheDrivesDirection) {
  auto p = single();
  p.set_drive(DriveDirection::Forward, 0.0);
  for (int i = 1; i <= 10; ++i) p.on_pulse(0.05 * i);
  EXPECT_EQ(p.count(), 10);
  p.set_drive(DriveDirection::Reverse, 1.0);
  for (int i = 1; i <= 4; ++i) p.on_pulse(1.0 + 0.05 * i);
  EXPECT_EQ(p.count(), 6);
  EXPECT_EQ(p.last_edge_s(), 1.2);
  EXPECT_EQ(p.errors(), 0U);
}

TEST(PulseCounter, CoastAfterStopCountsInTheLastDirection) {
  // K3NG's default: pulses while stopped belong to the last direction the motor turned.
  auto p = single();
  p.set_drive(DriveDirection::Reverse, 0.0);
  p.on_pulse(0.1);
  p.set_drive(DriveDirection::Stopped, 0.2);
  p.on_pulse(0.25);  // the motor coasts on
  p.on_pulse(0.40);
  EXPECT_EQ(p.count(), -3);
  EXPECT_EQ(p.ambiguous(), 0U);
}

TEST(PulseCounter, PulsesBeforeAnyMoveAreAmbiguousNotCounted) {
  auto p = single();
  p.set_drive(DriveDirection::Stopped, 0.0);
  p.on_pulse(0.1);  // wind on the dish, or a hand: no direction to count it in
  EXPECT_EQ(p.count(), 0);
  EXPECT_EQ(p.ambiguous(), 1U);
  EXPECT_FALSE(p.last_edge_s().has_value());
}

TEST(PulseCounter, AnEdgeReadLateCountsInTheDirectionOfItsTime) {
  auto p = single();
  p.set_drive(DriveDirection::Forward, 0.0);
  p.set_drive(DriveDirection::Reverse, 2.0);  // the tick reversed before the edge was read
  p.on_pulse(1.9);                            // … but it happened while going forward
  p.on_pulse(2.1);
  EXPECT_EQ(p.count(), 0);  // +1 −1
}

TEST(PulseCounter, DebounceDropsPulsesCloserThanTheMinimumSpacing) {
  auto p = single(0.010);
  p.set_drive(DriveDirection::Forward, 0.0);
  p.on_pulse(0.100);
  p.on_pulse(0.101);  // contact bounce
  p.on_pulse(0.1095);
  p.on_pulse(0.1102);  // just over 10 ms after the accepted one: a pulse
  p.on_pulse(0.130);
  EXPECT_EQ(p.count(), 3);
  EXPECT_EQ(p.bounces(), 2U);
}

TEST(PulseCounter, LinakPulseTrainSurvivesTheDebounce) {
  // LINAK's Hall output keeps pulse and pause ≥ 10 ms: a 20 ms period at full speed, with
  // bounce 1–3 ms after each real edge. Every real pulse counts, no bounce does.
  auto p = single(0.010);
  p.set_drive(DriveDirection::Forward, 0.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> bounce_s(0.001, 0.003);
  for (int i = 0; i < 500; ++i) {
    const double t = 1.0 + 0.020 * i;
    p.on_pulse(t);
    p.on_pulse(t + bounce_s(rng));
  }
  EXPECT_EQ(p.count(), 500);
  EXPECT_EQ(p.bounces(), 500U);
}

TEST(PulseCounter, HostileTimesAreErrorsNotCounts) {
  auto p = single();
  p.set_drive(DriveDirection::Forward, 0.0);
  p.on_pulse(1.0);
  p.on_pulse(0.5);  // backwards
  p.on_pulse(kNan);
  p.on_pulse(std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.count(), 1);
  EXPECT_EQ(p.errors(), 3U);
  p.on_quadrature_edge(QuadratureChannel::A, true, 2.0);  // wrong kind for this input
  EXPECT_EQ(p.errors(), 4U);
  EXPECT_EQ(p.count(), 1);
}

TEST(PulseCounter, QuadratureDirectionFromThePhase) {
  auto p = quadrature();
  // A leads B: 00 → 10 → 11 → 01 → 00, twice: 8 counts forward, whatever the drive says.
  p.set_drive(DriveDirection::Reverse, 0.0);
  double t = 0.0;
  for (int cycle = 0; cycle < 2; ++cycle) {
    p.on_quadrature_edge(QuadratureChannel::A, true, t += 0.001);
    p.on_quadrature_edge(QuadratureChannel::B, true, t += 0.001);
    p.on_quadrature_edge(QuadratureChannel::A, false, t += 0.001);
    p.on_quadrature_edge(QuadratureChannel::B, false, t += 0.001);
  }
  EXPECT_EQ(p.count(), 8);
  // B leads A: backwards.
  p.on_quadrature_edge(QuadratureChannel::B, true, t += 0.001);
  p.on_quadrature_edge(QuadratureChannel::A, true, t += 0.001);
  p.on_quadrature_edge(QuadratureChannel::B, false, t += 0.001);
  EXPECT_EQ(p.count(), 5);
  EXPECT_EQ(p.errors(), 0U);
}

TEST(PulseCounter, QuadratureBounceNetsZero) {
  auto p = quadrature();
  p.on_quadrature_edge(QuadratureChannel::A, true, 0.0010);
  p.on_quadrature_edge(QuadratureChannel::A, false, 0.0011);  // bounce
  p.on_quadrature_edge(QuadratureChannel::A, true, 0.0012);
  EXPECT_EQ(p.count(), 1);
  EXPECT_EQ(p.errors(), 0U);
}

TEST(PulseCounter, QuadratureLostEdgeIsAnError) {
  auto p = quadrature();
  p.on_quadrature_edge(QuadratureChannel::A, true, 0.001);
  p.on_quadrature_edge(QuadratureChannel::A, true, 0.002);  // A's falling edge never came
  EXPECT_EQ(p.count(), 1);
  EXPECT_EQ(p.errors(), 1U);
  p.on_pulse(0.003);  // a single-channel call on a quadrature input
  EXPECT_EQ(p.errors(), 2U);
}

TEST(PulseCounter, QuadratureReversedAndStartLevels) {
  auto p = quadrature(/*reversed=*/true);
  p.set_quadrature_levels(true, true);                       // the lines were both high at start-up
  p.on_quadrature_edge(QuadratureChannel::A, false, 0.001);  // 11 → 01: forward, reversed
  EXPECT_EQ(p.count(), -1);
  p.reset_count(100);
  p.on_quadrature_edge(QuadratureChannel::B, false, 0.002);  // 01 → 00: forward, reversed
  EXPECT_EQ(p.count(), 99);
}

}  // namespace
}  // namespace azt::control
