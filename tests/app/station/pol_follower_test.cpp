// The daemon's polarisation follower (station/pol_follower.hpp): the mode and Dpol turned into
// the pol axis's demand, the split following the transmitter's key, the hold while keyed, no DX
// holding, and Dpol computed at its nodes only. Time is the test's (UTC seconds), Dpol a given
// function of it.
#include "station/pol_follower.hpp"

#include <gtest/gtest.h>

namespace azt::app {
namespace {

/// Dpol turning 0.01°/s from 20° at t = 0, and how often it was computed.
struct Rig {
  int computed = 0;
  bool keyed = false;
  bool dx = true;
  PolFollower follower{PolFollowerParts{{},
                                        [this](double t) -> std::optional<double> {
                                          ++computed;
                                          if (!dx) return std::nullopt;
                                          return 20.0 + 0.01 * t;
                                        },
                                        [this] { return keyed; }}};

  control::PolDemand at(double t, control::PolSettings s) {
    follower.set_settings(s);
    return follower.demand(t);
  }
};

control::PolSettings mode(control::PolMode m, double dx_offset_deg = 0.0) {
  control::PolSettings s;
  s.mode = m;
  s.dx_offset_deg = dx_offset_deg;
  return s;
}

TEST(PolFollower, DxFollowsDpolWithItsRateFedForward) {
  Rig rig;
  const auto d = rig.at(1005.0, mode(control::PolMode::Dx, 3.0));
  ASSERT_TRUE(d.feed_deg.has_value());
  EXPECT_NEAR(*d.feed_deg, 20.0 + 10.05 + 3.0, 1e-9);
  EXPECT_NEAR(d.rate_deg_s, 0.01, 1e-12);
  EXPECT_NEAR(*rig.follower.dpol_deg(), 30.05, 1e-9);
}

TEST(PolFollower, DpolIsComputedOncePerNodeAndInterpolatedBetween) {
  Rig rig;
  rig.follower.set_settings(mode(control::PolMode::Dx));
  // A minute of 20 Hz ticks: two nodes at the start, then one per 10 s node crossed.
  for (int i = 0; i < 1200; ++i) (void)rig.follower.demand(1000.0 + i * 0.05);
  EXPECT_EQ(rig.computed, 2 + 5);
  rig.follower.forget_dpol();  // another DX station
  (void)rig.follower.demand(1060.0);
  EXPECT_EQ(rig.computed, 2 + 5 + 2);
}

TEST(PolFollower, SplitTurnsOnThePttByG3seksRule) {
  Rig rig;
  const auto rx = rig.at(0.0, mode(control::PolMode::Split, 15.0));
  rig.keyed = true;
  const auto tx = rig.follower.demand(0.0);
  ASSERT_TRUE(rx.feed_deg && tx.feed_deg);
  EXPECT_NEAR(*rx.feed_deg, 20.0 + 15.0, 1e-9);  // RX = S + offset
  EXPECT_NEAR(*tx.feed_deg, 20.0 - 15.0, 1e-9);  // TX = 2·S − RX = S − offset
  EXPECT_TRUE(rig.follower.transmitting());
}

TEST(PolFollower, HoldWhileKeyedHoldsInEveryMode) {
  Rig rig;
  control::PolSettings s = mode(control::PolMode::Fixed);
  s.fixed_deg = 45.0;
  s.hold_while_keyed = true;
  EXPECT_NEAR(*rig.at(0.0, s).feed_deg, 45.0, 1e-12);
  rig.keyed = true;
  const auto held = rig.at(0.05, s);
  EXPECT_FALSE(held.feed_deg.has_value());
  EXPECT_EQ(held.rate_deg_s, 0.0);
  s.mode = control::PolMode::Dx;
  EXPECT_FALSE(rig.at(0.1, s).feed_deg.has_value());
}

TEST(PolFollower, NoDxStationHolds) {
  Rig rig;
  rig.dx = false;
  EXPECT_FALSE(rig.at(0.0, mode(control::PolMode::Dx)).feed_deg.has_value());
  EXPECT_FALSE(rig.at(0.0, mode(control::PolMode::Split)).feed_deg.has_value());
  EXPECT_FALSE(rig.follower.dpol_deg().has_value());
  // Self needs no DX: its target is its offset.
  EXPECT_NEAR(*rig.at(0.0, mode(control::PolMode::Self)).feed_deg, 0.0, 1e-12);
}

TEST(PolFollower, ManualHoldsUntilGivenAnAngleAndHasNoRate) {
  Rig rig;
  EXPECT_FALSE(rig.at(0.0, mode(control::PolMode::Manual)).feed_deg.has_value());
  rig.follower.set_manual_deg(120.0);
  const auto d = rig.at(0.0, mode(control::PolMode::Manual));
  EXPECT_NEAR(*d.feed_deg, -60.0, 1e-9) << "folded to (−90, 90]";
  EXPECT_EQ(d.rate_deg_s, 0.0);
  EXPECT_FALSE(rig.at(0.0, mode(control::PolMode::Off)).feed_deg.has_value());
}

TEST(PolFollower, DpolAcrossTheFoldTakesTheShortWay) {
  int calls = 0;
  PolFollower f{PolFollowerParts{mode(control::PolMode::Dx),
                                 [&](double t) -> std::optional<double> {
                                   ++calls;
                                   return t < 5.0 ? 89.0 : -89.0;  // 2° apart across ±90°
                                 },
                                 [] { return false; }}};
  const auto d = f.demand(5.0);  // halfway between the nodes at 0 s and 10 s
  EXPECT_NEAR(*d.feed_deg, 90.0, 1e-9);
  EXPECT_NEAR(d.rate_deg_s, 0.2, 1e-12);
}

}  // namespace
}  // namespace azt::app
