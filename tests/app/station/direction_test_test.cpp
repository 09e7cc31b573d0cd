// The direction test (docs/hardware.md "Direction test"): the verdict from the reading, the
// refusals, and what ends it early.
#include "station/direction_test.hpp"

#include <gtest/gtest.h>

#include "support/station_rig.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

struct Rig : testing::StationRig {
  bool keyed = false;
  DirectionTest test{DirectionTestParts{antenna, commands, modes, [this] { return keyed; },
                                        [this] { return now_s; }}};
  std::optional<json> result;
  std::optional<std::string> error;

  std::optional<std::string> start(const std::string& axis) {
    return test.start(axis, "console 127.0.0.1", [this](json r, std::optional<std::string> e) {
      result = std::move(r);
      error = std::move(e);
    });
  }
  /// The daemon's tick: the test's demand (or the modes') to the antenna, then the test's look.
  void run(double seconds) {
    for (double end = now_s + seconds; now_s < end; now_s += 0.1) {
      const auto demand = test.demand(now_s).value_or(modes.demand(std::nullopt));
      antenna.set_pol_demand(test.pol_demand(now_s).value_or(control::PolDemand{}));
      antenna.tick(now_s, demand, {});
      test.tick(now_s);
    }
  }
};

TEST(DirectionTest, AnAxisThatFollowsTheCommandIsWiredRight) {
  Rig rig;
  rig.antenna.test_step_deg = 0.05;
  ASSERT_EQ(rig.start("el"), std::nullopt);
  EXPECT_EQ(rig.modes.mode(), control::Mode::Stop);  // the console's STOP first
  rig.run(0.5);
  EXPECT_FALSE(rig.result.has_value());
  rig.run(2.0);
  ASSERT_TRUE(rig.result.has_value());
  EXPECT_EQ(rig.error, std::nullopt);
  EXPECT_EQ((*rig.result)["axis"], "el");
  EXPECT_EQ((*rig.result)["commanded"], "up");
  EXPECT_EQ((*rig.result)["verdict"], "ok");
  EXPECT_DOUBLE_EQ((*rig.result)["before_deg"].get<double>(), 20.0);
  // Driven for one second of ticks (0.1 s apart), 0.05° each.
  EXPECT_NEAR((*rig.result)["moved_deg"].get<double>(), 0.5, 0.051);
  EXPECT_NEAR(rig.antenna.az_deg, 100.0, 1e-12);
  EXPECT_FALSE(rig.test.running());
}

TEST(DirectionTest, ThePolarisationAxisIsTestedThroughItsOwnDemand) {
  Rig rig;
  EXPECT_NE(rig.start("pol").value_or("").find("no polarisation axis"), std::string::npos);
  rig.antenna.pol_deg = 10.0;
  rig.antenna.test_step_deg = 0.05;
  ASSERT_EQ(rig.start("pol"), std::nullopt);
  rig.run(3.0);
  ASSERT_TRUE(rig.result.has_value());
  EXPECT_EQ((*rig.result)["axis"], "pol");
  EXPECT_EQ((*rig.result)["commanded"], "cw");
  EXPECT_EQ((*rig.result)["verdict"], "ok");
  EXPECT_NEAR((*rig.result)["moved_deg"].get<double>(), 0.5, 0.051);  // driven 1 s, then held
  EXPECT_NEAR(rig.antenna.az_deg, 100.0, 1e-12);
  EXPECT_NEAR(rig.antenna.el_deg, 20.0, 1e-12);
}

TEST(DirectionTest, AFixedElevationHasNoElevationToTest) {
  Rig rig;
  DirectionTest fixed{DirectionTestParts{rig.antenna, rig.commands, rig.modes, [] { return false; },
                                         [&rig] { return rig.now_s; }, true}};
  const auto refused = fixed.start("el", "console", [](json, std::optional<std::string>) {});
  EXPECT_NE(refused.value_or("").find("fixed"), std::string::npos);
  EXPECT_FALSE(fixed.running());
}

TEST(DirectionTest, AReadingGoingTheOtherWayIsReversedWiring) {
  Rig rig;
  rig.antenna.test_step_deg = 0.05;
  rig.antenna.reversed = true;
  ASSERT_EQ(rig.start("az"), std::nullopt);
  rig.run(2.0);
  ASSERT_TRUE(rig.result.has_value());
  EXPECT_EQ((*rig.result)["commanded"], "cw");
  EXPECT_EQ((*rig.result)["verdict"], "reversed");
  EXPECT_LT((*rig.result)["moved_deg"].get<double>(), -0.4);
}

TEST(DirectionTest, AReadingThatDoesNotMoveSaysSo) {
  Rig rig;
  rig.antenna.test_step_deg = 0.001;  // 0.01° in the second: below what counts as motion
  ASSERT_EQ(rig.start("az"), std::nullopt);
  rig.run(2.0);
  ASSERT_TRUE(rig.result.has_value());
  EXPECT_EQ((*rig.result)["verdict"], "no movement");
}

TEST(DirectionTest, IsRefusedWhileTrackingTransmittingFaultedOrLost) {
  {
    Rig rig;
    rig.modes.track("Sun");
    EXPECT_NE(rig.start("az").value_or("").find("tracking"), std::string::npos);
    EXPECT_EQ(rig.modes.mode(), control::Mode::Track);  // a refusal changes nothing
  }
  {
    Rig rig;
    rig.keyed = true;
    EXPECT_NE(rig.start("az").value_or("").find("transmitter"), std::string::npos);
  }
  {
    Rig rig;
    rig.antenna.faults_ = {"az: stall"};
    EXPECT_NE(rig.start("el").value_or("").find("az: stall"), std::string::npos);
  }
  {
    Rig rig;
    rig.antenna.lost = true;
    EXPECT_NE(rig.start("el").value_or("").find("unknown"), std::string::npos);
  }
  {
    Rig rig;
    EXPECT_NE(rig.start("sideways").value_or("").find("axis"), std::string::npos);
    EXPECT_FALSE(rig.test.running());
  }
}

TEST(DirectionTest, OneAtATime) {
  Rig rig;
  ASSERT_EQ(rig.start("az"), std::nullopt);
  EXPECT_NE(rig.start("el").value_or("").find("already"), std::string::npos);
}

TEST(DirectionTest, AnotherCommandOrAFaultEndsItUnfinished) {
  Rig rig;
  rig.antenna.test_step_deg = 0.05;
  ASSERT_EQ(rig.start("az"), std::nullopt);
  rig.run(0.3);
  rig.test.interrupt("console 127.0.0.1: STOP");
  ASSERT_TRUE(rig.error.has_value());
  EXPECT_NE(rig.error->find("STOP"), std::string::npos);
  EXPECT_FALSE(rig.test.demand(rig.now_s).has_value());  // nothing drives any more

  Rig faulted;
  faulted.antenna.test_step_deg = 0.05;
  ASSERT_EQ(faulted.start("el"), std::nullopt);
  faulted.run(0.3);
  faulted.antenna.faults_ = {"el: emergency stop input active"};
  faulted.run(0.2);
  ASSERT_TRUE(faulted.error.has_value());
  EXPECT_NE(faulted.error->find("emergency stop"), std::string::npos);
}

}  // namespace
}  // namespace azt::app
