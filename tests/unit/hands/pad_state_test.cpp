// A game pad's recorded event stream (evemu-record's text: "E: <time> <type> <code> <value>",
// type and code in hex) replayed through the pad's state into what the hands ask.
#include "azt/hands/pad_state.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace azt::hands {
namespace {

/// The state after replaying `recording`'s E: lines.
PadState replay(PadState state, const std::string& recording) {
  std::istringstream lines(recording);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream f(line);
    std::string tag;
    std::string time;
    unsigned type = 0;
    unsigned code = 0;
    int value = 0;
    if (!(f >> tag >> time >> std::hex >> type >> code >> std::dec >> value) || tag != "E:") {
      continue;
    }
    apply_pad_event(state, type, code, value);
  }
  return state;
}

/// An Xbox-class pad as xpad reports it (evemu-describe's A: lines: −32768…32767, flat 128;
/// the D-pad −1…1).
PadState xpad() {
  PadState s;
  s.ranges[kAbsX] = {-32768, 32767, 128};
  s.ranges[kAbsY] = {-32768, 32767, 128};
  s.ranges[kAbsHat0X] = {-1, 1, 0};
  s.ranges[kAbsHat0Y] = {-1, 1, 0};
  return s;
}

// The left stick pushed up and to the right, held, then A pressed and released.
constexpr const char* kStickUpRight = R"(# EVEMU 1.3
E: 0.000001 0003 0000 16000	# EV_ABS / ABS_X 16000
E: 0.000001 0003 0001 -24000	# EV_ABS / ABS_Y -24000
E: 0.000001 0000 0000 0000	# ------------ SYN_REPORT (0) ----------
E: 0.020011 0003 0000 20000	# EV_ABS / ABS_X 20000
E: 0.020011 0000 0000 0000	# ------------ SYN_REPORT (0) ----------
)";
constexpr const char* kPressA = R"(E: 0.500000 0001 0130 0001	# EV_KEY / BTN_SOUTH 1
E: 0.500000 0000 0000 0000	# ------------ SYN_REPORT (0) ----------
)";
constexpr const char* kReleaseAAndCentre =
    R"(E: 0.700000 0001 0130 0000	# EV_KEY / BTN_SOUTH 0
E: 0.700000 0003 0000 0	# EV_ABS / ABS_X 0
E: 0.700000 0003 0001 0	# EV_ABS / ABS_Y 0
E: 0.700000 0000 0000 0000	# ------------ SYN_REPORT (0) ----------
)";

TEST(PadState, TheRecordedStickIsASpeedOnEachAxisUpPositive) {
  const PadState s = replay(xpad(), kStickUpRight);
  const HandInputs in = pad_inputs(PadLayout{}, s);
  // 20000 of 32767.5 is 0.610; past the 0.15 dead zone: (0.610 − 0.15) / 0.85 = 0.542.
  EXPECT_NEAR(in.az_deflection, 0.542, 0.001);
  // −24000 is 0.732 down the axis, which is up: +(0.732 − 0.15) / 0.85 = +0.685.
  EXPECT_NEAR(in.el_deflection, 0.685, 0.001);
  EXPECT_FALSE(in.stop);
}

TEST(PadState, TheRecordedStreamDrivesHandControlToMoveThenStopThenNothing) {
  HandControl hands({1.0});
  PadState s = replay(xpad(), kStickUpRight);
  HandAction a = hands.update(pad_inputs(PadLayout{}, s));
  EXPECT_EQ(a.kind, HandActionKind::Move);
  EXPECT_GT(a.az_speed, 0.5);
  EXPECT_GT(a.el_speed, 0.6);
  s = replay(s, kPressA);
  EXPECT_EQ(hands.update(pad_inputs(PadLayout{}, s)).kind, HandActionKind::Stop);
  s = replay(s, kReleaseAAndCentre);
  EXPECT_EQ(hands.update(pad_inputs(PadLayout{}, s)).kind, HandActionKind::None);
  EXPECT_TRUE(s.pressed.empty());
}

TEST(PadState, TheDpadIsFourJogButtons) {
  PadState s = replay(xpad(), "E: 0.1 0003 0010 -1\nE: 0.1 0003 0011 -1\n");
  HandInputs in = pad_inputs(PadLayout{}, s);
  EXPECT_TRUE(in.ccw);
  EXPECT_TRUE(in.up);
  EXPECT_FALSE(in.cw);
  EXPECT_FALSE(in.down);
  PadLayout no_dpad;
  no_dpad.use_dpad = false;
  in = pad_inputs(no_dpad, s);
  EXPECT_FALSE(in.ccw);
  EXPECT_FALSE(in.up);
}

TEST(PadState, AnAxisThePadDoesNotHaveOrHasNotReportedIsNoDeflection) {
  PadState s;
  apply_pad_event(s, kEvAbs, kAbsX, 30000);  // a value with no range known
  const HandInputs in = pad_inputs(PadLayout{}, s);
  EXPECT_DOUBLE_EQ(in.az_deflection, 0.0);
  EXPECT_DOUBLE_EQ(in.el_deflection, 0.0);
}

TEST(PadState, AutorepeatKeepsAKeyHeldAndOtherEventTypesChangeNothing) {
  PadState s;
  apply_pad_event(s, kEvKey, kBtnStart, 1);
  apply_pad_event(s, kEvKey, kBtnStart, 2);
  EXPECT_TRUE(pad_inputs(PadLayout{}, s).park);
  apply_pad_event(s, 0x02, 0x00, 5);  // EV_REL
  apply_pad_event(s, 0x15, 0x50, 1);  // EV_FF
  EXPECT_TRUE(s.values.empty());
  apply_pad_event(s, kEvKey, kBtnStart, 0);
  EXPECT_FALSE(pad_inputs(PadLayout{}, s).park);
}

}  // namespace
}  // namespace azt::hands
