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

TEST(Modes, AllowingPcControlAfterAConsoleStopMovesNothingUntilAProgramAsks) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  ASSERT_TRUE(m.external(AzEl{10, 10}, "gpredict").ok());
  m.stop(/*from_console=*/true);
  EXPECT_TRUE(m.external_locked());
  EXPECT_FALSE(m.external(AzEl{20, 20}, "gpredict").ok());
  m.allow_external();
  EXPECT_FALSE(m.external_locked());
  EXPECT_EQ(m.mode(), Mode::External);
  // Not the last EXT position (10, 10) again: nothing until a program sends one.
  EXPECT_FALSE(m.demand(AzEl{50, 50}).position.has_value());
  EXPECT_FALSE(m.fixed_target().has_value());
  EXPECT_NE(m.demand(std::nullopt).reason.find("waiting"), std::string::npos);
  ASSERT_TRUE(m.external(AzEl{20, 20}, "gpredict").ok());
  EXPECT_DOUBLE_EQ(m.demand(std::nullopt).position->az_deg, 20);
  EXPECT_DOUBLE_EQ(m.fixed_target()->el_deg, 20);
}

TEST(Modes, AJogStopsWhenItsClientFallsSilentForOneSecond) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  ASSERT_TRUE(m.external_jog(Jog{1, 0}, "rotctld 127.0.0.1:4000", 10.0).ok());
  EXPECT_EQ(m.mode(), Mode::External);
  ASSERT_TRUE(m.demand(std::nullopt).jog.has_value());
  EXPECT_FALSE(m.demand(std::nullopt).position.has_value());
  // Another client's traffic is no keep-alive; the jogging client's is.
  m.heard_from("rotctld 127.0.0.1:5000", 10.9);
  m.heard_from("rotctld 127.0.0.1:4000", 10.6);
  m.update(11.5);
  EXPECT_EQ(m.mode(), Mode::External);
  m.update(11.61);
  EXPECT_EQ(m.mode(), Mode::Stop);
  EXPECT_FALSE(m.demand(std::nullopt).jog.has_value());
  EXPECT_NE(m.who().find("silent"), std::string::npos);
}

TEST(Modes, AJogNeedsADirection) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  EXPECT_FALSE(m.external_jog(Jog{0, 0}, "c", 0.0).ok());
  EXPECT_FALSE(m.external_jog(Jog{2, 0}, "c", 0.0).ok());
  EXPECT_EQ(m.mode(), Mode::Stop);
}

TEST(Modes, AJogsSpeedIsAFractionOfFullRateAndAnIdleAxisNeedsNone) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  EXPECT_FALSE(m.external_jog(Jog{1, 0, 0.0, 1.0}, "c", 0.0).ok());
  EXPECT_FALSE(m.external_jog(Jog{1, 0, 1.5, 1.0}, "c", 0.0).ok());
  EXPECT_FALSE(m.external_jog(Jog{0, -1, 1.0, std::nan("")}, "c", 0.0).ok());
  EXPECT_EQ(m.mode(), Mode::Stop);
  ASSERT_TRUE(m.external_jog(Jog{0, -1, 0.0, 0.25}, "c", 0.0).ok());
  EXPECT_DOUBLE_EQ(m.demand(std::nullopt).jog->el_speed, 0.25);
}

TEST(Modes, AManualJogIsManAndIsNotLockedOutByAConsoleStop) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  m.stop(true);
  ASSERT_TRUE(m.manual_jog(Jog{-1, 0, 0.5, 1.0}, "buttons", 1.0).ok());
  EXPECT_EQ(m.mode(), Mode::Manual);
  EXPECT_EQ(m.demand(std::nullopt).reason, "MAN move by buttons");
  EXPECT_EQ(m.demand(std::nullopt).jog->az, -1);
  m.update(2.01);  // the same keep-alive as a program's
  EXPECT_EQ(m.mode(), Mode::Stop);
}

TEST(Modes, EndingAJogStopsOnlyTheJogOfThatSource) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  ASSERT_TRUE(m.manual_jog(Jog{1, 0}, "buttons", 0.0).ok());
  m.end_jog("game pad");
  EXPECT_EQ(m.mode(), Mode::Manual);
  m.end_jog("buttons");
  EXPECT_EQ(m.mode(), Mode::Stop);
  EXPECT_EQ(m.who(), "released by buttons");
  // Another source took over meanwhile: letting go changes nothing.
  ASSERT_TRUE(m.manual_jog(Jog{1, 0}, "buttons", 0.0).ok());
  m.track("Moon");
  m.end_jog("buttons");
  EXPECT_EQ(m.mode(), Mode::Track);
}

TEST(Modes, ALocalStopLocksProgramsOutAndNamesWhoPressedIt) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  ASSERT_TRUE(m.external(AzEl{200, 20}, "gpredict").ok());
  m.local_stop("buttons");
  EXPECT_EQ(m.mode(), Mode::Stop);
  EXPECT_EQ(m.who(), "buttons");
  EXPECT_TRUE(m.external_locked());
  EXPECT_FALSE(m.external(AzEl{210, 20}, "gpredict").ok());
}

TEST(Modes, APositionTargetIsHeldWithoutKeepAlive) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  ASSERT_TRUE(m.external(AzEl{200, 20}, "gpredict").ok());
  m.update(1e6);
  EXPECT_EQ(m.mode(), Mode::External);
  EXPECT_DOUBLE_EQ(m.fixed_target()->az_deg, 200);
}

TEST(Modes, AConsoleStopLocksOutProgramsUntilTheConsoleChoosesAgain) {
  ModeController m(slots(), OutOfRangePolicy::Hold, 0.0);
  ASSERT_TRUE(m.external(AzEl{200, 20}, "gpredict").ok());
  m.stop(true);
  EXPECT_TRUE(m.external_locked());
  EXPECT_FALSE(m.external(AzEl{210, 20}, "gpredict").ok());
  EXPECT_FALSE(m.external_jog(Jog{1, 0}, "gpredict", 0.0).ok());
  EXPECT_EQ(m.mode(), Mode::Stop);
  m.track("Moon");
  EXPECT_FALSE(m.external_locked());
  EXPECT_TRUE(m.external(AzEl{210, 20}, "gpredict").ok());
  // A program's own STOP does not lock anyone out.
  m.stop();
  EXPECT_TRUE(m.external(AzEl{211, 20}, "gpredict").ok());
}

}  // namespace
}  // namespace azt::control
