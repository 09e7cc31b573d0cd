#include "azt/control/pol_target.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "azt/eme/polarisation.hpp"

namespace azt::control {
namespace {

constexpr double kTol = 1e-9;

PolSettings settings(PolMode mode, double dx_offset_deg = 0.0) {
  PolSettings s;
  s.mode = mode;
  s.fixed_deg = 12.5;
  s.self_offset_deg = -33.0;
  s.dx_offset_deg = dx_offset_deg;
  return s;
}

PolInputs inputs(std::optional<double> spatial_deg, bool transmitting = false) {
  PolInputs in;
  in.spatial_offset_deg = spatial_deg;
  in.transmitting = transmitting;
  return in;
}

TEST(PolMode, NamesRoundTripAndUnknownNamesAreRefusedWithTheList) {
  for (const PolMode m : {PolMode::Off, PolMode::Fixed, PolMode::Manual, PolMode::Self, PolMode::Dx,
                          PolMode::Split}) {
    const auto parsed = parse_pol_mode(to_string(m));
    ASSERT_TRUE(parsed.ok()) << to_string(m);
    EXPECT_EQ(*parsed, m);
  }
  const auto bad = parse_pol_mode("DX");  // exactly the lower-case names
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("off, fixed, manual, self, dx or split"), std::string::npos);
  EXPECT_FALSE(parse_pol_mode("").ok());
}

TEST(FoldLinear, FoldsToTheHalfOpenRangeMinus90To90) {
  EXPECT_NEAR(fold_linear_deg(100.0), -80.0, kTol);
  EXPECT_NEAR(fold_linear_deg(90.0), 90.0, kTol);
  EXPECT_NEAR(fold_linear_deg(-90.0), 90.0, kTol);  // the same polarisation, on the open side
  EXPECT_NEAR(fold_linear_deg(270.0), 90.0, kTol);
  EXPECT_NEAR(fold_linear_deg(-135.0), 45.0, kTol);
  EXPECT_NEAR(fold_linear_deg(180.0), 0.0, kTol);
  EXPECT_NEAR(fold_linear_deg(-400.0), -40.0, kTol);  // −400 + 360
}

TEST(PolFeed, OffHasNoTargetFixedAndSelfTheirAngles) {
  EXPECT_FALSE(pol_feed_deg(settings(PolMode::Off), inputs(30.0)).has_value());
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Fixed), inputs(std::nullopt)), 12.5, kTol);
  // Self: our own echo has no spatial offset, whatever the DX's Dpol: only the peaked Faraday.
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Self), inputs(30.0)), -33.0, kTol);
}

TEST(PolFeed, ManualFollowsTheOperatorAndHoldsUntilGivenAnAngle) {
  PolInputs in = inputs(std::nullopt);
  EXPECT_FALSE(pol_feed_deg(settings(PolMode::Manual), in).has_value());
  in.manual_deg = 135.0;
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Manual), in), -45.0, kTol);  // 135 − 180
}

TEST(PolFeed, DxIsDpolPlusTheOffsetAndHoldsWithoutADxStation) {
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Dx, 10.0), inputs(30.0)), 40.0, kTol);
  // 80 + 20 = 100, the same linear polarisation as −80.
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Dx, 20.0), inputs(80.0)), -80.0, kTol);
  EXPECT_FALSE(pol_feed_deg(settings(PolMode::Dx, 10.0), inputs(std::nullopt)).has_value());
  // Transmitting changes nothing in DX mode.
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Dx, 10.0), inputs(30.0, true)), 40.0, kTol);
}

TEST(PolFeed, SplitTransmitsAtG3seksAngle) {
  // S = 30, RX = 40 (Faraday correction +10): TX = 2·30 − 40 = 20.
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Split, 10.0), inputs(30.0, false)), 40.0, kTol);
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Split, 10.0), inputs(30.0, true)), 20.0, kTol);
  // S = 80, RX = 100 ≡ −80, TX = 160 − 100 = 60.
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Split, 20.0), inputs(80.0, true)), 60.0, kTol);
  // S = −70, RX = −30, TX = −140 + 30 = −110 ≡ 70.
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Split, 40.0), inputs(-70.0, true)), 70.0, kTol);
}

TEST(PolFeed, SplitReproducesG3seksSpecialCases) {
  // DUBUS 3/1996 (pol_target.hpp): Faraday 0° or 90°: TX = RX; 45°: 90° between them.
  const double s = 25.0;
  for (const double faraday : {0.0, 90.0}) {
    const auto rx = pol_feed_deg(settings(PolMode::Split, faraday), inputs(s, false));
    const auto tx = pol_feed_deg(settings(PolMode::Split, faraday), inputs(s, true));
    EXPECT_NEAR(*rx, *tx, kTol) << faraday;
  }
  const auto rx = pol_feed_deg(settings(PolMode::Split, 45.0), inputs(s, false));
  const auto tx = pol_feed_deg(settings(PolMode::Split, 45.0), inputs(s, true));
  EXPECT_NEAR(std::fabs(*rx - *tx), 90.0, kTol);  // 70 and −20
}

TEST(PolFeed, SplitFromWsjtxParallacticAngles) {
  // round3-notes §8's worked station: φ 50°, δ 10°, H −30° gives WSJT-X's p = +26.04°. A DX
  // station seeing p = −40.00: Dpol = mod(−40 − 26.04 + 720, 180) = 113.96, −180 → −66.04.
  const double s = eme::dpol_deg(26.04, -40.0);
  EXPECT_NEAR(s, -66.04, 1e-9);
  // RX = −66.04 + 10 = −56.04; TX = 2·(−66.04) + 56.04 = −76.04.
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Split, 10.0), inputs(s, false)), -56.04, 1e-9);
  EXPECT_NEAR(*pol_feed_deg(settings(PolMode::Split, 10.0), inputs(s, true)), -76.04, 1e-9);
}

TEST(PolFeed, HoldWhileKeyedGivesNoTargetWhileTransmittingInEveryMode) {
  for (const PolMode m : {PolMode::Fixed, PolMode::Self, PolMode::Dx, PolMode::Split}) {
    PolSettings s = settings(m, 10.0);
    s.hold_while_keyed = true;
    EXPECT_FALSE(pol_feed_deg(s, inputs(30.0, true)).has_value()) << to_string(m);
    EXPECT_TRUE(pol_feed_deg(s, inputs(30.0, false)).has_value()) << to_string(m);
  }
}

TEST(PolFeed, ANonFiniteAngleIsNoTarget) {
  PolInputs in = inputs(std::nullopt);
  in.manual_deg = std::nan("");
  EXPECT_FALSE(pol_feed_deg(settings(PolMode::Manual), in).has_value());
}

TEST(PolTravel, MustBeFiniteAndSpanHalfATurn) {
  EXPECT_TRUE(PolTravel::make(-95.0, 95.0).ok());
  EXPECT_TRUE(PolTravel::make(0.0, 180.0).ok());
  EXPECT_FALSE(PolTravel::make(-80.0, 80.0).ok());  // 160°: some angles out of reach
  EXPECT_FALSE(PolTravel::make(std::nan(""), 95.0).ok());
}

TEST(PlanPolMount, TheEquivalentAngleInTheTravelNearestThePresentOne) {
  const PolTravel travel{-95.0, 95.0};
  EXPECT_NEAR(plan_pol_mount(80.0, -80.0, travel), -80.0, kTol);  // 100 lies past 95
  EXPECT_NEAR(plan_pol_mount(-60.0, 90.0, travel), -90.0, kTol);  // −90 is 30° away, 90 is 150
  EXPECT_NEAR(plan_pol_mount(60.0, 90.0, travel), 90.0, kTol);
  EXPECT_NEAR(plan_pol_mount(-85.0, 88.0, travel), -92.0, kTol);  // 5° past the fold, not 173
  EXPECT_NEAR(plan_pol_mount(0.0, -30.0, PolTravel{0.0, 180.0}), 150.0, kTol);
}

TEST(PlanPolMount, NeverAsksForMoreThanTheTravel) {
  const PolTravel travel{-95.0, 95.0};
  for (double present = -95.0; present <= 95.0; present += 5.0) {
    for (double feed = -89.0; feed <= 90.0; feed += 7.0) {
      const double mount = plan_pol_mount(present, feed, travel);
      EXPECT_GE(mount, travel.min_deg);
      EXPECT_LE(mount, travel.max_deg);
      EXPECT_NEAR(fold_linear_deg(mount), fold_linear_deg(feed), 1e-9);
      EXPECT_LE(std::fabs(mount - present), 180.0);
    }
  }
  // A travel narrower than half a turn (never made by PolTravel::make) still bounds the answer.
  EXPECT_NEAR(plan_pol_mount(0.0, 80.0, PolTravel{-45.0, 45.0}), 45.0, kTol);
}

}  // namespace
}  // namespace azt::control
