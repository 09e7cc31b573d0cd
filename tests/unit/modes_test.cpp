#include "azt/control/modes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::control {
namespace {

std::array<ParkSlot, 4> slots() {
  return {{{"home", {180, 0}}, {"stow", {0, 90}}, {"wind", {270, 10}}, {"service", {90, 5}}}};
}

TEST(Modes, StartsStopped) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  EXPECT_EQ(m.mode(), Mode::Stop);
  EXPECT_FALSE(m.demand(AzEl{10, 10}).position.has_value());
}

TEST(Modes, TrackFollowsTheSkyAndHoldsOrParksBelowTheHorizon) {
  ModeController hold(slots(), OutOfRangePolicy::Hold, 0.0);
  hold.track("Moon");
  EXPECT_EQ(hold.demand(AzEl{100, 20}).position->az_deg, 100);
  const Demand set = hold.demand(AzEl{250, -3});
  EXPECT_FALSE(set.position.has_value());
  EXPECT_NE(set.reason.find("below the horizon"), std::string::npos);
  ModeController park(slots(), OutOfRangePolicy::Park, 5.0);
  park.track("Sun");
  EXPECT_EQ(park.demand(AzEl{250, 3}).position->az_deg, 180);  // slot 1
}

TEST(Modes, ManualParkExternalAndStop) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  ASSERT_TRUE(m.manual(AzEl{123.45, 30}).ok());
  EXPECT_EQ(m.mode(), Mode::Manual);
  EXPECT_DOUBLE_EQ(m.demand(std::nullopt).position->az_deg, 123.45);
  ASSERT_TRUE(m.park(2).ok());
  EXPECT_EQ(m.who(), "stow");
  EXPECT_DOUBLE_EQ(m.demand(std::nullopt).position->el_deg, 90);
  EXPECT_FALSE(m.park(5).ok());
  EXPECT_EQ(m.mode(), Mode::Park);  // a refused request changes nothing
  ASSERT_TRUE(m.external(AzEl{10, 10}, "gpredict 127.0.0.1:50123").ok());
  EXPECT_EQ(m.mode(), Mode::External);
  EXPECT_EQ(to_string(m.mode()), "EXT");
  EXPECT_FALSE(m.manual(AzEl{400, 10}).ok());
  EXPECT_FALSE(m.manual(AzEl{10, std::nan("")}).ok());
  m.stop();
  EXPECT_FALSE(m.demand(AzEl{1, 1}).position.has_value());
}

}  // namespace
}  // namespace azt::control
