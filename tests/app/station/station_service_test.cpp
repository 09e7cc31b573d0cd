// StationService: what PC programs' requests do to the station's modes (docs/daemon.md), through
// the station's front door.
#include "station/station_service.hpp"

#include <gtest/gtest.h>

#include "support/station_rig.hpp"

namespace azt::app {
namespace {

using proto::ServiceStatus;

struct ServiceRig : testing::StationRig {
  StationService service{commands,       modes,
                         antenna,        [this] { return now_s; },
                         "test station", [](const std::string&) {}};
};

TEST(StationService, APositionTargetPutsTheStationInExtMode) {
  ServiceRig rig;
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Ok);
  EXPECT_EQ(rig.modes.mode(), control::Mode::External);
  ASSERT_TRUE(rig.modes.fixed_target().has_value());
  EXPECT_DOUBLE_EQ(rig.modes.fixed_target()->az_deg, 120.0);
  ASSERT_EQ(rig.accepted.size(), 1U);
  EXPECT_EQ(rig.accepted[0], "rotctld a: position az 120.00° el 30.00°");
}

TEST(StationService, ALatchedFaultRefusesEveryMotionRequest) {
  ServiceRig rig;
  rig.antenna.faults_ = {"az: stall: driven for 2 s but moved less than 0.5 deg"};
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Rejected);
  EXPECT_EQ(rig.service.goto_axis("rotctld a", proto::Axis::Az, 120.0), ServiceStatus::Rejected);
  EXPECT_EQ(rig.service.move("rotctld a", proto::AxisMotion{1, 0}), ServiceStatus::Rejected);
  EXPECT_EQ(rig.service.park("rotctld a"), ServiceStatus::Rejected);
  EXPECT_NE(rig.modes.mode(), control::Mode::External);
  ASSERT_TRUE(rig.service.position().has_value());  // the position is still reported
  EXPECT_TRUE(rig.service.position()->fault);
  EXPECT_EQ(rig.refused.size(), 4U);
  EXPECT_TRUE(rig.accepted.empty());
  rig.antenna.clear_faults();  // an operator's decision
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Ok);
}

TEST(StationService, InvalidTargetsAreInvalidNotRejected) {
  ServiceRig rig;
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 95.0), ServiceStatus::Invalid);
  rig.antenna.faults_ = {"el: runaway"};
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 95.0), ServiceStatus::Invalid);
}

TEST(StationService, AConsoleStopLocksProgramsOutUntilTheConsoleChooses) {
  ServiceRig rig;
  rig.commands.stop(testing::console_source());
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Rejected);
  EXPECT_EQ(rig.service.park("rotctld a"), ServiceStatus::Rejected);
  EXPECT_EQ(rig.modes.mode(), control::Mode::Stop);
  ASSERT_TRUE(rig.commands.point(testing::console_source(), ParkTarget{2}).accepted());
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Ok);
}

TEST(StationService, StoppingOneAxisWhileFaultedStopsEverything) {
  ServiceRig rig;
  ASSERT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Ok);
  rig.antenna.faults_ = {"az: stall"};
  rig.service.stop("rotctld a", proto::Axis::Az);
  EXPECT_EQ(rig.modes.mode(), control::Mode::Stop);
}

}  // namespace
}  // namespace azt::app
