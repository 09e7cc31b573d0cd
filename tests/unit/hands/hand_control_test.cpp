#include "azt/hands/hand_control.hpp"

#include <gtest/gtest.h>

namespace azt::hands {
namespace {

HandInputs held(bool HandInputs::*button) {
  HandInputs in;
  in.*button = true;
  return in;
}

TEST(HandControl, AHeldButtonAsksForAMoveEveryTickAndLettingGoReleasesOnce) {
  HandControl hands({0.5});
  for (int tick = 0; tick < 3; ++tick) {
    const HandAction a = hands.update(held(&HandInputs::cw));
    EXPECT_EQ(a.kind, HandActionKind::Move);
    EXPECT_DOUBLE_EQ(a.az_speed, 0.5);
    EXPECT_DOUBLE_EQ(a.el_speed, 0.0);
  }
  EXPECT_EQ(hands.update({}).kind, HandActionKind::Release);
  EXPECT_EQ(hands.update({}).kind, HandActionKind::None);
}

TEST(HandControl, EachButtonMovesItsAxisItsWay) {
  HandControl hands({1.0});
  EXPECT_DOUBLE_EQ(hands.update(held(&HandInputs::ccw)).az_speed, -1.0);
  EXPECT_DOUBLE_EQ(hands.update(held(&HandInputs::up)).el_speed, 1.0);
  EXPECT_DOUBLE_EQ(hands.update(held(&HandInputs::down)).el_speed, -1.0);
}

TEST(HandControl, BothButtonsOfOneAxisCancel) {
  HandControl hands({1.0});
  HandInputs in;
  in.cw = in.ccw = true;
  EXPECT_EQ(hands.update(in).kind, HandActionKind::None);
  in.up = true;
  const HandAction a = hands.update(in);
  EXPECT_EQ(a.kind, HandActionKind::Move);
  EXPECT_DOUBLE_EQ(a.az_speed, 0.0);
  EXPECT_DOUBLE_EQ(a.el_speed, 1.0);
}

TEST(HandControl, TheSticksDeflectionIsTheSpeedAndAButtonOverridesIt) {
  HandControl hands({1.0});
  HandInputs in;
  in.az_deflection = -0.3;
  in.el_deflection = 0.6;
  HandAction a = hands.update(in);
  EXPECT_DOUBLE_EQ(a.az_speed, -0.3);
  EXPECT_DOUBLE_EQ(a.el_speed, 0.6);
  in.cw = true;
  a = hands.update(in);
  EXPECT_DOUBLE_EQ(a.az_speed, 1.0);
  EXPECT_DOUBLE_EQ(a.el_speed, 0.6);
}

TEST(HandControl, StopActsOnThePressOnceAndNothingMovesWhileItIsHeld) {
  HandControl hands({1.0});
  ASSERT_EQ(hands.update(held(&HandInputs::cw)).kind, HandActionKind::Move);
  HandInputs in = held(&HandInputs::stop);
  in.cw = true;
  EXPECT_EQ(hands.update(in).kind, HandActionKind::Stop);
  EXPECT_EQ(hands.update(in).kind, HandActionKind::None);
  EXPECT_EQ(hands.update(in).kind, HandActionKind::None);
  in.stop = false;  // released with CW still held: the move starts again
  EXPECT_EQ(hands.update(in).kind, HandActionKind::Move);
}

TEST(HandControl, ParkActsOnThePressOnce) {
  HandControl hands({1.0});
  EXPECT_EQ(hands.update(held(&HandInputs::park)).kind, HandActionKind::Park);
  EXPECT_EQ(hands.update(held(&HandInputs::park)).kind, HandActionKind::None);
  EXPECT_EQ(hands.update({}).kind, HandActionKind::None);
  EXPECT_EQ(hands.update(held(&HandInputs::park)).kind, HandActionKind::Park);
}

TEST(HandControl, ParkDuringAMoveEndsTheMoveWithoutAReleaseAfterIt) {
  HandControl hands({1.0});
  ASSERT_EQ(hands.update(held(&HandInputs::up)).kind, HandActionKind::Move);
  EXPECT_EQ(hands.update(held(&HandInputs::park)).kind, HandActionKind::Park);
  EXPECT_EQ(hands.update({}).kind, HandActionKind::None);
}

TEST(HandActionKind, EveryKindHasAName) {
  EXPECT_EQ(to_string(HandActionKind::Move), "move");
  EXPECT_EQ(to_string(HandActionKind::Release), "release");
  EXPECT_EQ(to_string(HandActionKind::Stop), "stop");
  EXPECT_EQ(to_string(HandActionKind::Park), "park");
  EXPECT_EQ(to_string(HandActionKind::None), "none");
}

}  // namespace
}  // namespace azt::hands
