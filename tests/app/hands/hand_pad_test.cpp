// A game pad at the mast through the front door (docs/hardware.md, "Buttons and a game pad"):
// recorded input events (evemu-record's lines) replayed into a pad's state, the pad unplugged and
// plugged in again, the same rules as every other source.
#include "hands/hand_pad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "support/station_rig.hpp"

namespace azt::app {
namespace {

/// A pad whose events the test replays (an Xbox-class pad's ranges, as xpad reports them).
class RecordedPad final : public linux_os::EvdevPad {
 public:
  RecordedPad() {
    state_.ranges[hands::kAbsX] = {-32768, 32767, 128};
    state_.ranges[hands::kAbsY] = {-32768, 32767, 128};
    state_.ranges[hands::kAbsHat0X] = {-1, 1, 0};
    state_.ranges[hands::kAbsHat0Y] = {-1, 1, 0};
  }
  /// evemu-record's "E: <time> <type> <code> <value>" lines, type and code in hex.
  void replay(const std::string& recording) {
    std::istringstream lines(recording);
    std::string tag;
    std::string time;
    unsigned type = 0;
    unsigned code = 0;
    int value = 0;
    while (lines >> tag >> time >> std::hex >> type >> code >> std::dec >> value) {
      if (tag == "E:") hands::apply_pad_event(state_, type, code, value);
    }
  }
  [[nodiscard]] const hands::PadState& state() const override { return state_; }
  [[nodiscard]] const std::string& name() const override { return name_; }
  [[nodiscard]] bool present() const override { return present_; }

  bool present_ = true;

 private:
  hands::PadState state_;
  std::string name_ = "Microsoft X-Box 360 pad";
};

constexpr const char* kStickHalfRight = "E: 0.000001 0003 0000 16384\nE: 0.000001 0000 0000 0000\n";
constexpr const char* kStickFullUp = "E: 0.000001 0003 0001 -32768\nE: 0.000001 0000 0000 0000\n";
constexpr const char* kStickCentred =
    "E: 0.5 0003 0000 0\nE: 0.5 0003 0001 0\nE: 0.5 0000 0000 0000\n";
constexpr const char* kPressA = "E: 0.7 0001 0130 1\nE: 0.7 0000 0000 0000\n";

/// The pad on a standing station, ticked every 50 ms as the daemon does. `plugged` is the pad the
/// next open finds (nullptr: no such device).
struct Mast {
  testing::StationRig rig;
  std::unique_ptr<RecordedPad> plugged = std::make_unique<RecordedPad>();
  RecordedPad* pad = plugged.get();
  int opens = 0;
  std::vector<std::string> log;
  GamepadConfig config{"/dev/input/by-id/usb-pad-event-joystick", 0.15, 1.0, 2};
  HandPad hands{config,
                [this](const std::string& path) -> Result<std::unique_ptr<linux_os::EvdevPad>> {
                  ++opens;
                  if (!plugged) return fail(path + ": No such file or directory");
                  pad = plugged.get();
                  return std::unique_ptr<linux_os::EvdevPad>(std::move(plugged));
                },
                rig.commands, [this] { return rig.now_s; },
                [this](const std::string& line) { log.push_back(line); }};

  void run_for(double seconds) {
    for (long tick = std::lround(seconds / 0.05); tick > 0; --tick) {
      rig.now_s += 0.05;
      hands.tick();
      rig.modes.update(rig.now_s);
    }
  }
  [[nodiscard]] control::Demand demand() const { return rig.modes.demand(std::nullopt); }
};

TEST(HandPad, TheStickMovesAtItsDeflectionAndCentringStops) {
  Mast mast;
  mast.run_for(0.05);
  mast.pad->replay(kStickHalfRight);
  mast.run_for(2.0);
  ASSERT_TRUE(mast.demand().jog.has_value());
  EXPECT_EQ(mast.demand().jog->az, 1);
  EXPECT_EQ(mast.demand().jog->el, 0);
  // Half deflection is half speed once past the dead zone: (0.5 − 0.15) / 0.85 = 41 %, as 40 %.
  EXPECT_NEAR(mast.demand().jog->az_speed, 0.40, 0.026);
  ASSERT_EQ(mast.rig.accepted.size(), 1U);
  EXPECT_EQ(mast.rig.commands.control().holder, "hands");
  mast.pad->replay(kStickCentred);
  mast.run_for(0.1);
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Stop);
  EXPECT_EQ(mast.rig.modes.who(), "released by game pad");
}

TEST(HandPad, ThePadGoingAwayLetsGoAndItIsFoundAgainWhenPluggedIn) {
  Mast mast;
  mast.run_for(0.05);
  const nlohmann::json connected = mast.hands.to_json();  // what the console shows
  EXPECT_EQ(connected["device"], "/dev/input/by-id/usb-pad-event-joystick");
  EXPECT_EQ(connected["connected"], true);
  EXPECT_EQ(connected["name"], "Microsoft X-Box 360 pad");
  EXPECT_TRUE(connected["error"].is_null());
  mast.pad->replay(kStickFullUp);
  mast.run_for(0.5);
  ASSERT_TRUE(mast.demand().jog.has_value());
  EXPECT_EQ(mast.demand().jog->el, 1);
  mast.pad->present_ = false;  // unplugged with the stick held
  mast.run_for(0.05);
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Stop);
  EXPECT_EQ(mast.log.back(),
            "game pad: Microsoft X-Box 360 pad went away; looking for it every 2 s");
  EXPECT_EQ(mast.hands.to_json()["connected"], false);
  EXPECT_TRUE(mast.hands.to_json()["error"].is_null()) << "looked for, no reason yet";
  // Not there for 5 s: looked for at 2 s and 4 s, the reason logged once.
  mast.run_for(5.0);
  EXPECT_EQ(mast.opens, 3);
  EXPECT_EQ(mast.log.back(),
            "game pad: /dev/input/by-id/usb-pad-event-joystick: No such file or directory");
  EXPECT_EQ(mast.hands.to_json()["error"],
            "/dev/input/by-id/usb-pad-event-joystick: No such file or directory");
  EXPECT_TRUE(mast.hands.to_json()["name"].is_null());
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Stop);
  mast.plugged = std::make_unique<RecordedPad>();
  mast.run_for(1.5);  // the next look, at 6.6 s
  EXPECT_EQ(mast.opens, 4);
  EXPECT_EQ(mast.hands.connected_name(), "Microsoft X-Box 360 pad");
  mast.pad->replay(kStickHalfRight);
  mast.run_for(0.1);
  ASSERT_TRUE(mast.demand().jog.has_value());
  EXPECT_EQ(mast.demand().jog->az, 1);
}

TEST(HandPad, AStickHeldThroughAnEStopIsRefusedOnceAndAStopsTheAntenna) {
  Mast mast;
  mast.rig.antenna.faults_ = {"E-stop input active"};
  mast.run_for(0.05);
  mast.pad->replay(kStickHalfRight);
  mast.run_for(2.0);
  ASSERT_EQ(mast.rig.refused.size(), 1U);
  EXPECT_EQ(mast.rig.refused[0], "game pad: a fault is latched (E-stop input active)");
  EXPECT_FALSE(mast.demand().jog.has_value());
  mast.rig.antenna.faults_.clear();
  mast.pad->replay(kStickCentred);
  mast.pad->replay(kPressA);
  mast.run_for(0.1);
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Stop);
  EXPECT_EQ(mast.rig.accepted.back(), "game pad: STOP");
}

TEST(HandPad, AMissingPadIsNoErrorAndNothingMoves) {
  Mast mast;
  mast.plugged.reset();
  mast.pad = nullptr;
  mast.run_for(3.0);
  EXPECT_EQ(mast.opens, 2);  // at once, then 2 s later
  EXPECT_EQ(mast.log.size(), 1U);
  EXPECT_TRUE(mast.hands.connected_name().empty());
  EXPECT_TRUE(mast.rig.accepted.empty());
}

}  // namespace
}  // namespace azt::app
