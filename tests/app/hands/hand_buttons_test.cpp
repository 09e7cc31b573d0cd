// The buttons at the mast through the front door (docs/hardware.md, "Buttons and a game pad"):
// recorded presses on fake GPIO lines, the same rules as every other source.
#include "hands/hand_buttons.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>

#include "common/usage_error.hpp"
#include "support/fake_gpio.hpp"
#include "support/station_rig.hpp"

namespace azt::app {
namespace {

using testing::program_source;

linux_os::GpioLineSpec line(unsigned offset, const std::string& name) {
  return linux_os::GpioLineSpec{"gpiochip0", offset, true, "[gpio] button_" + name};
}

ButtonsConfig wired() {
  ButtonsConfig b;
  b.cw = line(5, "cw");
  b.ccw = line(6, "ccw");
  b.up = line(13, "up");
  b.down = line(19, "down");
  b.stop = line(20, "stop");
  b.park = line(21, "park");
  b.park_slot = 2;
  return b;
}

/// The buttons on a standing station, ticked every 50 ms as the daemon does.
struct Mast {
  boost::asio::io_context io;
  testing::FakeGpio gpio{io};
  testing::StationRig rig;
  HandButtons buttons{wired(), gpio, rig.commands, [this] { return rig.now_s; }};

  void set(const std::string& name, bool pressed) {
    gpio.set_input("[gpio] button_" + name, pressed);
    io.poll();
    io.restart();
  }
  void run_for(double seconds) {
    for (double t = 0.0; t < seconds - 1e-9; t += 0.05) {
      rig.now_s += 0.05;
      buttons.tick();
      rig.modes.update(rig.now_s);
    }
  }
  [[nodiscard]] control::Demand demand() const { return rig.modes.demand(std::nullopt); }
};

TEST(HandButtons, AHeldButtonMovesItsAxisAndLettingGoStopsAtOnce) {
  Mast mast;
  mast.set("cw", true);
  mast.run_for(3.0);  // three times the continuous move's keep-alive
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Manual);
  ASSERT_TRUE(mast.demand().jog.has_value());
  EXPECT_EQ(mast.demand().jog->az, 1);
  EXPECT_EQ(mast.demand().jog->el, 0);
  ASSERT_EQ(mast.rig.accepted.size(), 1U);  // asked once, then only kept alive
  EXPECT_EQ(mast.rig.accepted[0],
            "buttons: continuous move az +1 el 0 (stops after 1 s without traffic)");
  EXPECT_EQ(mast.rig.commands.control().holder, "hands");
  mast.set("cw", false);
  mast.run_for(0.1);  // the 30 ms debounce and the next tick
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Stop);
  EXPECT_EQ(mast.rig.modes.who(), "released by buttons");
}

TEST(HandButtons, ContactBounceShorterThanTheDebounceMovesNothing) {
  Mast mast;
  for (int i = 0; i < 3; ++i) {
    mast.set("up", true);
    mast.rig.now_s += 0.005;
    mast.set("up", false);
    mast.rig.now_s += 0.005;
  }
  mast.run_for(0.5);
  EXPECT_TRUE(mast.rig.accepted.empty());
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Stop);
}

TEST(HandButtons, StopLocksPcProgramsOutAsTheConsolesStopDoes) {
  Mast mast;
  ASSERT_TRUE(mast.rig.commands.point(program_source(), PositionTarget{120.0, 10.0}).accepted());
  mast.set("stop", true);
  mast.run_for(0.1);
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Stop);
  const auto outcome = mast.rig.commands.point(program_source(), PositionTarget{130.0, 10.0});
  ASSERT_FALSE(outcome.accepted());
  EXPECT_EQ(outcome.refusal->reason, "PC programs are locked out: STOP was pressed (buttons)");
  // The hands themselves still move the antenna after their STOP.
  mast.set("stop", false);
  mast.set("down", true);
  mast.run_for(0.1);
  ASSERT_TRUE(mast.demand().jog.has_value());
  EXPECT_EQ(mast.demand().jog->el, -1);
}

TEST(HandButtons, AButtonHeldThroughALatchedFaultIsRefusedOnceAndNotRetried) {
  Mast mast;
  mast.rig.antenna.faults_ = {"E-stop input active"};
  mast.set("ccw", true);
  mast.run_for(2.0);
  ASSERT_EQ(mast.rig.refused.size(), 1U);
  EXPECT_EQ(mast.rig.refused[0], "buttons: a fault is latched (E-stop input active)");
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Stop);
  // Cleared, then pressed again: the press is a new one.
  mast.rig.antenna.faults_.clear();
  mast.set("ccw", false);
  mast.run_for(0.1);
  mast.set("ccw", true);
  mast.run_for(0.1);
  ASSERT_TRUE(mast.demand().jog.has_value());
  EXPECT_EQ(mast.demand().jog->az, -1);
}

TEST(HandButtons, ParkGoesToItsSlotOnce) {
  Mast mast;
  mast.set("park", true);
  mast.run_for(1.0);
  EXPECT_EQ(mast.rig.modes.mode(), control::Mode::Park);
  EXPECT_EQ(mast.rig.modes.who(), "stow");
  EXPECT_EQ(mast.rig.accepted.size(), 1U);
}

TEST(HandButtons, BothButtonsOfAnAxisMoveNothing) {
  Mast mast;
  mast.set("cw", true);
  mast.set("ccw", true);
  mast.run_for(0.5);
  EXPECT_TRUE(mast.rig.accepted.empty());
}

TEST(HandButtons, ALineThatCannotBeHadIsAUsageErrorNamingItsKey) {
  boost::asio::io_context io;
  testing::FakeGpio gpio{io};
  gpio.make_busy(13);
  testing::StationRig rig;
  try {
    HandButtons buttons{wired(), gpio, rig.commands, [] { return 0.0; }};
    FAIL() << "a busy line was taken";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("button_up"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace azt::app
