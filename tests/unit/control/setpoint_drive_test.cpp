// The digital-pot setpoint drive (seed 001: an MCP41010, 256 taps, replacing the control pot of a
// rotator box that closes its own loop). Worked values use a 450° rotator calibrated at its ends,
// code 0 at 0° and code 255 at 450° (450/255 = 30/17 ≈ 1.7647° per code), so that
// 90° → 51 and 180° → 102 exactly.
#include "azt/control/setpoint_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>

namespace azt::control {
namespace {

constexpr double kTol = 1e-9;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

SetpointCalibration rotator450() {
  const auto c = SetpointCalibration::make(0.0, 0.0, 255.0, 450.0);
  EXPECT_TRUE(c.ok());
  return c.ok() ? *c : SetpointCalibration{};
}

TEST(SetpointCalibration, Validates) {
  EXPECT_TRUE(SetpointCalibration::make(0.0, 0.0, 255.0, 450.0).ok());
  EXPECT_TRUE(SetpointCalibration::make(12.5, 3.0, 240.0, 447.0).ok());  // measured, fractional
  EXPECT_FALSE(SetpointCalibration::make(-1.0, 0.0, 255.0, 450.0).ok());
  EXPECT_FALSE(SetpointCalibration::make(0.0, 0.0, 256.0, 450.0).ok());  // no code 256
  EXPECT_FALSE(SetpointCalibration::make(100.0, 0.0, 100.0, 450.0).ok());
  EXPECT_FALSE(SetpointCalibration::make(0.0, 90.0, 255.0, 90.0).ok());
  EXPECT_FALSE(SetpointCalibration::make(0.0, kNan, 255.0, 450.0).ok());
  EXPECT_FALSE(SetpointCalibration::make(kNan, 0.0, 255.0, 450.0).ok());
  const auto r = SetpointCalibration::make(0.0, 0.0, 300.0, 450.0);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("0 to 255"), std::string::npos);
}

TEST(SetpointCalibration, WorkedValuesOfA450DegreeRotator) {
  const SetpointCalibration c = rotator450();
  EXPECT_EQ(c.wiper_from_deg(0.0), 0.0);
  EXPECT_EQ(c.wiper_from_deg(450.0), 255.0);  // exact: the end is not "clamped" by rounding
  EXPECT_NEAR(c.wiper_from_deg(90.0), 51.0, kTol);
  EXPECT_NEAR(c.wiper_from_deg(180.0), 102.0, kTol);
  EXPECT_NEAR(c.wiper_from_deg(225.0), 127.5, kTol);
  EXPECT_NEAR(c.deg_from_wiper(128.0), 225.0 + 30.0 / 17.0 / 2.0, kTol);
  EXPECT_NEAR(c.deg_from_wiper(51.0), 90.0, kTol);
  EXPECT_NEAR(c.step_deg(), 30.0 / 17.0, kTol);
}

TEST(SetpointCalibration, ReversedAndMeasuredPoints) {
  // A pot wired the other way round: code 0 at 450°, 255 at 0°.
  const auto reversed = SetpointCalibration::make(0.0, 450.0, 255.0, 0.0);
  ASSERT_TRUE(reversed.ok());
  EXPECT_NEAR(reversed->wiper_from_deg(90.0), 204.0, kTol);
  // Points measured inside the range: code 20 at 10°, code 235 at 440° (0.5 code per degree).
  // Codes 0 and 255 then reach −30° and 480°.
  const auto measured = SetpointCalibration::make(20.0, 10.0, 235.0, 440.0);
  ASSERT_TRUE(measured.ok());
  EXPECT_NEAR(measured->wiper_from_deg(100.0), 65.0, kTol);
  EXPECT_NEAR(measured->deg_from_wiper(0.0), -30.0, kTol);
  EXPECT_NEAR(measured->deg_from_wiper(255.0), 480.0, kTol);
  EXPECT_NEAR(measured->step_deg(), 2.0, kTol);
}

TEST(SetpointDrive, SendsOnlyOnChange) {
  SetpointDrive d(rotator450());
  EXPECT_FALSE(d.last_sent());
  auto u = d.update(90.0);
  EXPECT_EQ(u.send, std::optional<std::uint8_t>(51));
  EXPECT_EQ(u.wiper, 51);
  EXPECT_EQ(u.status, SetpointStatus::InRange);
  EXPECT_FALSE(d.update(90.0).send);  // unchanged: nothing on the bus
  u = d.update(90.5);                 // 51.28 rounds to the same code
  EXPECT_FALSE(u.send);
  EXPECT_EQ(u.wiper, 51);
  EXPECT_EQ(d.update(91.0).send, std::optional<std::uint8_t>(52));  // 51.57 → 52
  EXPECT_EQ(d.last_sent(), std::optional<std::uint8_t>(52));
  EXPECT_EQ(d.update(90.0).send, std::optional<std::uint8_t>(51));  // and back
}

TEST(SetpointDrive, HalfCodesRoundAwayFromZero) {
  SetpointDrive d(rotator450());
  EXPECT_EQ(d.update(225.0).wiper, 128);  // 127.5
}

TEST(SetpointDrive, ForceResendAfterReconnect) {
  // The pot comes back at mid-scale after a power loss: the code must be rewritten even though
  // the target has not changed.
  SetpointDrive d(rotator450());
  ASSERT_TRUE(d.update(90.0).send);
  ASSERT_FALSE(d.update(90.0).send);
  d.force_resend();
  EXPECT_FALSE(d.last_sent());
  EXPECT_EQ(d.update(90.0).send, std::optional<std::uint8_t>(51));
  EXPECT_FALSE(d.update(90.0).send);
}

TEST(SetpointDrive, ClampsToTheEndsAndSaysSo) {
  SetpointDrive d(rotator450());
  auto u = d.update(500.0);
  EXPECT_EQ(u.wiper, 255);
  EXPECT_EQ(u.send, std::optional<std::uint8_t>(255));
  EXPECT_TRUE(u.clamped());
  u = d.update(450.0);  // the end itself is in range; same code, nothing sent
  EXPECT_FALSE(u.clamped());
  EXPECT_FALSE(u.send);
  u = d.update(450.1);  // just past the end: rounds to 255 anyway, but is reported
  EXPECT_TRUE(u.clamped());
  EXPECT_EQ(u.wiper, 255);
  u = d.update(-10.0);
  EXPECT_TRUE(u.clamped());
  EXPECT_EQ(u.send, std::optional<std::uint8_t>(0));
  EXPECT_FALSE(d.update(0.0).clamped());
  EXPECT_EQ(d.update(1e300).wiper, 255);
  EXPECT_EQ(d.update(-1e300).wiper, 0);
}

TEST(SetpointDrive, NonFiniteTargetsSendNothing) {
  SetpointDrive d(rotator450());
  ASSERT_TRUE(d.update(90.0).send);
  for (const double bad : {kNan, std::numeric_limits<double>::infinity()}) {
    const auto u = d.update(bad);
    EXPECT_EQ(u.status, SetpointStatus::NotFinite);
    EXPECT_FALSE(u.send);
    EXPECT_FALSE(u.clamped());
  }
  EXPECT_EQ(d.last_sent(), std::optional<std::uint8_t>(51));  // the box keeps its setpoint
  EXPECT_FALSE(d.update(90.0).send);
}

TEST(SetpointDrive, ASweepSendsEachCodeOnce) {
  // A target sweeping the whole range in 0.01° steps: 45 001 updates, 256 writes.
  SetpointDrive d(rotator450());
  int sends = 0;
  std::optional<std::uint8_t> previous;
  for (int k = 0; k <= 45000; ++k) {
    const auto u = d.update(static_cast<double>(k) * 0.01);
    if (u.send) {
      ++sends;
      if (previous) {
        EXPECT_EQ(*u.send, *previous + 1);  // no code skipped, none repeated
      }
      previous = u.send;
    }
    EXPECT_FALSE(u.clamped());
  }
  EXPECT_EQ(sends, 256);
}

// Seeded random property: inside the range the chosen code turns the rotator to within half a
// step of the target, and the code is sent exactly when it differs from the last one.
TEST(SetpointDrive, RandomTargetsLandWithinHalfAStep) {
  const auto cal = SetpointCalibration::make(12.5, 3.0, 240.0, 447.0);
  ASSERT_TRUE(cal.ok());
  SetpointDrive d(*cal);
  std::mt19937_64 rng(0x5e7901);
  const double lo = cal->deg_from_wiper(0.0);
  const double hi = cal->deg_from_wiper(255.0);
  std::uniform_real_distribution<double> target_deg(lo, hi);
  for (int k = 0; k < 100000; ++k) {
    const double target = target_deg(rng);
    const std::optional<std::uint8_t> before = d.last_sent();
    const auto u = d.update(target);
    ASSERT_EQ(u.status, SetpointStatus::InRange) << target;
    ASSERT_LE(std::fabs(cal->deg_from_wiper(u.wiper) - target), cal->step_deg() / 2.0 + kTol);
    ASSERT_EQ(u.send.has_value(), before != u.wiper) << target;
    ASSERT_EQ(d.last_sent(), std::optional<std::uint8_t>(u.wiper));
  }
}

}  // namespace
}  // namespace azt::control

namespace azt::control {
namespace {

// DS11195 figure 5-1: command byte xx01xx01 with the don't-care bits 0 selects "write data" to
// potentiometer 0; the data byte follows.
TEST(Mcp41010Frame, CommandByteThenWiper) {
  for (const int wiper : {0, 1, 128, 254, 255}) {
    const auto frame = mcp41010_write_frame(static_cast<std::uint8_t>(wiper));
    EXPECT_EQ(frame[0] & 0x30, 0x10) << "command bits C1 C0 = 01 (write data)";
    EXPECT_EQ(frame[0] & 0x03, 0x01) << "pot select P1 P0 = 01 (potentiometer 0)";
    EXPECT_EQ(frame[1], wiper);
  }
  static_assert(mcp41010_write_frame(0x80)[0] == 0x11);
}

}  // namespace
}  // namespace azt::control
