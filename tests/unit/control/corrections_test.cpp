// Position corrections against the worked examples of the AnTrack-Pro manual (seed 000,
// "SECTION B" and the "Antenna Correction" / tilt table screens).
#include "azt/control/corrections.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace azt::control {
namespace {

constexpr double kTol = 1e-9;

TEST(AxisOffsets, SeedExampleMinusThreeFortyReadsZero) {
  // Seed: "our encoder is reading not 0.00 but -03.40 … we apply the correction "positive" of
  // +03.40 degrees to obtain the required 0.00."
  PositionCorrections c;
  c.offsets = *AxisOffsets::make(0.0, 3.40);
  EXPECT_EQ(apply_corrections(0.0, -3.40, c).el_deg, 0.0);
  // The same reading from a 0–360 elevation encoder (the EncoderHub sends 356.60).
  EXPECT_NEAR(apply_corrections(0.0, 356.60, c).el_deg, 0.0, kTol);
}

TEST(AxisOffsets, AzimuthOffsetWrapsThroughNorth) {
  PositionCorrections c;
  c.offsets = *AxisOffsets::make(5.0, 0.0);
  EXPECT_NEAR(apply_corrections(358.0, 10.0, c).az_deg, 3.0, kTol);
  c.offsets = *AxisOffsets::make(-5.0, 0.0);
  EXPECT_NEAR(apply_corrections(2.0, 10.0, c).az_deg, 357.0, kTol);
}

TEST(AxisOffsets, Validates) {
  EXPECT_TRUE(AxisOffsets::make(-360.0, 180.0).ok());
  EXPECT_FALSE(AxisOffsets::make(360.5, 0.0).ok());
  EXPECT_FALSE(AxisOffsets::make(0.0, -180.5).ok());
  EXPECT_FALSE(AxisOffsets::make(std::nan(""), 0.0).ok());
  EXPECT_FALSE(AxisOffsets::make(0.0, std::numeric_limits<double>::infinity()).ok());
}

TEST(UserCorrections, StepsAreHundredthsOfADegree) {
  UserCorrections u;
  for (int i = 0; i < 7; ++i) EXPECT_TRUE(u.nudge_el(+1));  // UP ×7
  EXPECT_EQ(u.el_steps(), 7);
  EXPECT_EQ(u.el_deg(), 0.07);  // exactly the double the display's "0.07" denotes
  EXPECT_TRUE(u.nudge_az(-123));
  EXPECT_EQ(u.az_deg(), -1.23);
  u.reset();
  EXPECT_EQ(u.az_deg(), 0.0);
  EXPECT_EQ(u.el_deg(), 0.0);
}

TEST(UserCorrections, NoDriftAfterTenThousandPresses) {
  UserCorrections u;
  for (int i = 0; i < 987; ++i) u.nudge_el(+1);
  for (int i = 0; i < 10000; ++i) u.nudge_el(i % 2 == 0 ? -1 : +1);  // DWN, UP, DWN, UP …
  EXPECT_EQ(u.el_deg(), 9.87);
  // 10 000 presses of "+": the first 1000 reach the ±10.00° limit exactly, the rest are refused.
  int accepted = 0;
  for (int i = 0; i < 10000; ++i) accepted += u.nudge_az(+1) ? 1 : 0;
  EXPECT_EQ(accepted, 1000);
  EXPECT_EQ(u.az_deg(), 10.0);
  for (int i = 0; i < 1999; ++i) u.nudge_az(-1);
  EXPECT_EQ(u.az_deg(), -9.99);
}

TEST(UserCorrections, LargeNudgesSaturateWithoutOverflow) {
  UserCorrections u;
  EXPECT_FALSE(u.nudge_el(2147483647));
  EXPECT_EQ(u.el_deg(), 10.0);
  EXPECT_FALSE(u.nudge_el(-2147483647 - 1));
  EXPECT_EQ(u.el_deg(), -10.0);
}

TEST(UserCorrections, FromStoredDegrees) {
  const auto u = UserCorrections::from_deg(0.07, -1.23);
  ASSERT_TRUE(u.ok());
  EXPECT_EQ(u->az_steps(), 7);
  EXPECT_EQ(u->el_steps(), -123);
  EXPECT_EQ(UserCorrections::from_deg(10.0, -10.0)->az_steps(), 1000);
  EXPECT_FALSE(UserCorrections::from_deg(10.02, 0.0).ok());
  EXPECT_FALSE(UserCorrections::from_deg(0.0, std::nan("")).ok());
}

TEST(UserCorrections, UpMakesTheAntennaPointHigher) {
  // Target elevation 30.00 with UP pressed 7 times: the controller drives the corrected reading
  // onto the target, which happens when the encoder reads 30.07 — 0.07° higher.
  PositionCorrections c;
  for (int i = 0; i < 7; ++i) c.user.nudge_el(+1);
  EXPECT_NEAR(apply_corrections(100.0, 30.07, c).el_deg, 30.00, kTol);
  // "+" on the azimuth buttons: the antenna ends up clockwise of the target.
  c.user.nudge_az(+50);
  EXPECT_NEAR(apply_corrections(100.50, 30.07, c).az_deg, 100.00, kTol);
  // DWN past zero points lower.
  c.user.nudge_el(-10);
  EXPECT_NEAR(apply_corrections(100.0, 29.97, c).el_deg, 30.00, kTol);
}

std::vector<double> sample_tilt() {
  std::vector<double> e(TiltTable::kEntries, 0.0);
  e[0] = 0.10;    // 000°
  e[1] = 0.40;    // 006°
  e[58] = 0.00;   // 348°
  e[59] = -0.20;  // 354°
  return e;
}

TEST(TiltTable, InterpolatesBetweenEntries) {
  const auto t = TiltTable::make(sample_tilt());
  ASSERT_TRUE(t.ok());
  EXPECT_NEAR(t->correction_el_deg(0.0), 0.10, kTol);
  EXPECT_NEAR(t->correction_el_deg(3.0), 0.25, kTol);
  EXPECT_NEAR(t->correction_el_deg(4.5), 0.325, kTol);
  EXPECT_NEAR(t->correction_el_deg(6.0), 0.40, kTol);
  EXPECT_NEAR(t->correction_el_deg(9.0), 0.20, kTol);
  EXPECT_NEAR(t->correction_el_deg(180.0), 0.0, kTol);
}

TEST(TiltTable, WrapsFromEntry59At354ToEntry0At360) {
  const auto t = TiltTable::make(sample_tilt());
  ASSERT_TRUE(t.ok());
  EXPECT_NEAR(t->correction_el_deg(351.0), -0.10, kTol);
  EXPECT_NEAR(t->correction_el_deg(354.0), -0.20, kTol);
  EXPECT_NEAR(t->correction_el_deg(357.0), -0.05, kTol);
  EXPECT_NEAR(t->correction_el_deg(359.4), 0.07, kTol);
  EXPECT_NEAR(t->correction_el_deg(std::nextafter(360.0, 0.0)), 0.10, kTol);
  EXPECT_NEAR(t->correction_el_deg(360.0), 0.10, kTol);
  EXPECT_NEAR(t->correction_el_deg(-3.0), -0.05, kTol);
  EXPECT_NEAR(t->correction_el_deg(363.0), 0.25, kTol);
  EXPECT_NEAR(t->correction_el_deg(720.0), 0.10, kTol);
  EXPECT_TRUE(std::isnan(t->correction_el_deg(std::nan(""))));
}

TEST(TiltTable, ContinuousAllTheWayRound) {
  const auto t = TiltTable::make(sample_tilt());
  ASSERT_TRUE(t.ok());
  // Steepest slope in the table is 0.40° per 6° (006° → 012°): a 0.001° step changes the
  // correction by 0.0000667° at most, also across 354° → 360°; a seam would jump.
  double previous = t->correction_el_deg(0.0);
  for (int k = 1; k <= 360000; ++k) {
    const double now = t->correction_el_deg(k * 0.001);
    ASSERT_LE(std::fabs(now - previous), 0.00007) << "at " << k * 0.001;
    previous = now;
  }
}

TEST(TiltTable, DefaultIsNoCorrection) {
  const TiltTable t;
  EXPECT_EQ(t.correction_el_deg(123.4), 0.0);
}

TEST(TiltTable, ValidatesSizeAndBounds) {
  EXPECT_FALSE(TiltTable::make(std::vector<double>(59, 0.0)).ok());
  EXPECT_FALSE(TiltTable::make(std::vector<double>(61, 0.0)).ok());
  auto e = sample_tilt();
  e[30] = 5.0;
  EXPECT_TRUE(TiltTable::make(e).ok());
  e[30] = -5.01;
  const auto bad = TiltTable::make(e);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("entry 30"), std::string::npos);
  e[30] = std::nan("");
  EXPECT_FALSE(TiltTable::make(e).ok());
}

TEST(TiltTable, WithEntryReplacesOne) {
  const TiltTable t;
  const auto u = t.with_entry(59, -0.30);
  ASSERT_TRUE(u.ok());
  EXPECT_NEAR(u->correction_el_deg(354.0), -0.30, kTol);
  EXPECT_EQ(t.correction_el_deg(354.0), 0.0);  // the original is a value, untouched
  EXPECT_FALSE(t.with_entry(60, 0.0).ok());
  EXPECT_FALSE(t.with_entry(0, 6.0).ok());
}

TEST(ApplyCorrections, OrderOffsetThenUserThenTilt) {
  PositionCorrections c;
  c.offsets = *AxisOffsets::make(6.0, 3.40);
  c.tilt = *TiltTable::make(sample_tilt());
  for (int i = 0; i < 100; ++i) c.user.nudge_el(+1);  // UP 1.00
  // Raw azimuth 351 + offset 6 = 357: the tilt is looked up there (−0.05), not at the raw 351
  // (which would give −0.10, halfway between entries 58 and 59).
  const CorrectedPosition p = apply_corrections(351.0, 10.0, c);
  EXPECT_NEAR(p.az_deg, 357.0, kTol);
  EXPECT_NEAR(p.tilt_el_deg, -0.05, kTol);
  EXPECT_NEAR(p.el_deg, 12.35, kTol);  // 10.00 raw, +3.40 offset, UP 1.00, tilt −0.05
}

TEST(ApplyCorrections, NoCorrectionsIsIdentity) {
  const PositionCorrections none;
  const CorrectedPosition p = apply_corrections(123.45, 67.89, none);
  EXPECT_EQ(p.az_deg, 123.45);
  EXPECT_EQ(p.el_deg, 67.89);
  EXPECT_EQ(p.tilt_el_deg, 0.0);
}

TEST(Normalize, AzimuthAndElevationRanges) {
  EXPECT_EQ(normalize_az_deg(-10.0), 350.0);
  EXPECT_EQ(normalize_az_deg(360.0), 0.0);
  EXPECT_NEAR(normalize_el_deg(356.60), -3.40, kTol);
  EXPECT_EQ(normalize_el_deg(180.0), 180.0);  // flip mounts keep their upper half
  EXPECT_EQ(normalize_el_deg(-90.0), -90.0);
  EXPECT_EQ(normalize_el_deg(270.0), -90.0);
  EXPECT_EQ(normalize_el_deg(-91.0), 269.0);
}

}  // namespace
}  // namespace azt::control

namespace azt::control {
namespace {

TEST(Corrections, ThePointingModelActsAfterTheEncoderOffsetAndBeforeTheUserCorrection) {
  // The model says where the beam points for the mount's (offset-corrected) angles: an
  // elevation index error of 0.2° (the encoder reads 0.2° high) lowers the reading by 0.2°; the
  // user's UP still raises the pointing on top of it; the contributions are shown.
  PositionCorrections c;
  c.offsets = AxisOffsets::make(1.0, 0.5).value();
  c.model.ie_deg = 0.2;
  c.model.ia_deg = -0.3;
  c.user = UserCorrections::from_deg(0.0, 0.1).value();
  const CorrectedPosition p = apply_corrections(100.0, 30.0, c);
  EXPECT_NEAR(p.az_deg, 101.3, 1e-9);
  EXPECT_NEAR(p.el_deg, 30.5 - 0.2 - 0.1, 1e-9);
  EXPECT_NEAR(p.model_az_deg, 0.3, 1e-9);
  EXPECT_NEAR(p.model_el_deg, -0.2, 1e-9);
  // No model: nothing changes and nothing is shown.
  const CorrectedPosition plain = apply_corrections(100.0, 30.0, PositionCorrections{});
  EXPECT_DOUBLE_EQ(plain.az_deg, 100.0);
  EXPECT_DOUBLE_EQ(plain.model_el_deg, 0.0);
}

}  // namespace
}  // namespace azt::control
