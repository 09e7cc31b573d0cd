// The station's front door (docs/daemon.md): every source meets the same rules and is recorded.
#include "station/station_commands.hpp"

#include <gtest/gtest.h>

#include "support/station_rig.hpp"

namespace azt::app {
namespace {

using proto::ServiceStatus;
using testing::console_source;
using testing::program_source;

/// The console's and a program's answers to the same position on fresh stations.
std::pair<CommandOutcome, CommandOutcome> both_ask(double az_deg, double el_deg,
                                                   bool faulted = false) {
  testing::StationRig console_rig;
  testing::StationRig program_rig;
  if (faulted) {
    console_rig.antenna.faults_ = {"az: stall"};
    program_rig.antenna.faults_ = {"az: stall"};
  }
  return {console_rig.commands.point(console_source(), PositionTarget{az_deg, el_deg}),
          program_rig.commands.point(program_source(), PositionTarget{az_deg, el_deg})};
}

void expect_same_refusal(const CommandOutcome& a, const CommandOutcome& b, ServiceStatus status) {
  ASSERT_FALSE(a.accepted());
  ASSERT_FALSE(b.accepted());
  EXPECT_EQ(a.refusal->status, status);
  EXPECT_EQ(b.refusal->status, status);
  EXPECT_EQ(a.refusal->reason, b.refusal->reason);
  EXPECT_EQ(a.refusal->field, b.refusal->field);
}

TEST(StationCommands, ConsoleAndProgramsAcceptTheSameOverlapAzimuth) {
  const auto [console, program] = both_ask(400.0, 10.0);
  ASSERT_TRUE(console.accepted());
  ASSERT_TRUE(program.accepted());
  EXPECT_EQ(console.mode, "MAN");
  EXPECT_EQ(program.mode, "EXT");
}

TEST(StationCommands, ConsoleAndProgramsRefuseTheSameAzimuthOutsideTheTravel) {
  const auto [console, program] = both_ask(500.0, 10.0);
  expect_same_refusal(console, program, ServiceStatus::Invalid);
  EXPECT_EQ(console.refusal->field, "az_deg");
  EXPECT_NE(console.refusal->reason.find("500"), std::string::npos);
}

TEST(StationCommands, ConsoleAndProgramsAreRefusedAlikeWhileAFaultIsLatched) {
  const auto [console, program] = both_ask(120.0, 10.0, true);
  expect_same_refusal(console, program, ServiceStatus::Rejected);
  EXPECT_NE(console.refusal->reason.find("az: stall"), std::string::npos);
}

TEST(StationCommands, EveryMotionCommandIsRefusedWhileAFaultIsLatched) {
  testing::StationRig rig;
  rig.antenna.faults_ = {"el: runaway"};
  for (const TargetRequest& r :
       {TargetRequest{NamedTarget{"moon"}}, TargetRequest{RaDecTarget{83.6, 22.0}},
        TargetRequest{ParkTarget{1}}}) {
    const auto outcome = rig.commands.point(console_source(), r);
    ASSERT_FALSE(outcome.accepted());
    EXPECT_EQ(outcome.refusal->status, ServiceStatus::Rejected);
  }
  EXPECT_FALSE(rig.commands.jog(program_source(), control::Jog{1, 0}).accepted());
  EXPECT_EQ(rig.modes.mode(), control::Mode::Stop);
  EXPECT_EQ(rig.refused.size(), 4U);
  rig.commands.stop(console_source());  // STOP is always accepted
  EXPECT_EQ(rig.accepted.size(), 1U);
}

TEST(StationCommands, AnElevationBeyondTheTravelNamesItsField) {
  testing::StationRig rig;
  const auto outcome = rig.commands.point(console_source(), PositionTarget{10.0, 95.0});
  ASSERT_FALSE(outcome.accepted());
  EXPECT_EQ(outcome.refusal->field, "el_deg");
  EXPECT_EQ(rig.refused.size(), 1U);
}

TEST(StationCommands, NamedTargetsAreTrackedAndUnknownOnesRefused) {
  testing::StationRig rig;
  const auto moon = rig.commands.point(console_source(), target_from_name("MOON"));
  ASSERT_TRUE(moon.accepted());
  EXPECT_EQ(moon.mode, "TRACK");
  EXPECT_EQ(moon.target, "Moon");
  const auto vega = rig.commands.point(console_source(), target_from_name("vega"));
  ASSERT_FALSE(vega.accepted());
  EXPECT_EQ(vega.refusal->field, "name");
  EXPECT_EQ(rig.modes.who(), "Moon");  // a refusal changes nothing
}

TEST(StationCommands, ASatelliteNeedsACatalogue) {
  testing::StationRig rig;
  const auto outcome = rig.commands.point(console_source(), target_from_name("sat:ISS"));
  ASSERT_FALSE(outcome.accepted());
  EXPECT_EQ(outcome.refusal->field, "name");
  EXPECT_FALSE(rig.commands.tracking_satellite());
}

TEST(StationCommands, RaDecAndParkSlotsAreCheckedWithTheirFields) {
  testing::StationRig rig;
  auto bad_ra = rig.commands.point(console_source(), RaDecTarget{400.0, 0.0});
  ASSERT_FALSE(bad_ra.accepted());
  EXPECT_EQ(bad_ra.refusal->field, "ra_deg");
  auto bad_dec = rig.commands.point(console_source(), RaDecTarget{10.0, 95.0});
  ASSERT_FALSE(bad_dec.accepted());
  EXPECT_EQ(bad_dec.refusal->field, "dec_deg");
  auto bad_slot = rig.commands.point(console_source(), ParkTarget{5});
  ASSERT_FALSE(bad_slot.accepted());
  EXPECT_EQ(bad_slot.refusal->field, "park");
  auto stow = rig.commands.point(program_source(), ParkTarget{2});
  ASSERT_TRUE(stow.accepted());
  EXPECT_EQ(stow.target, "stow");
}

TEST(StationCommands, EachAcceptedCommandIsRecordedWithItsSource) {
  testing::StationRig rig;
  ASSERT_TRUE(rig.commands.point(program_source(), PositionTarget{-90.0, 45.0}).accepted());
  ASSERT_TRUE(rig.commands.point(console_source(), target_from_name("sun")).accepted());
  ASSERT_EQ(rig.accepted.size(), 2U);
  EXPECT_EQ(rig.accepted[0], "rotctld 127.0.0.1:50000: position az -90.00° el 45.00°");
  EXPECT_EQ(rig.accepted[1], "console 127.0.0.1: track Sun");
  EXPECT_EQ(rig.commands.commander(), "console 127.0.0.1");
}

TEST(StationCommands, AProgramsAzimuthIsTakenInItsOwnConvention) {
  testing::StationRig rig;
  ASSERT_TRUE(rig.commands.point(program_source(), PositionTarget{-90.0, 45.0}).accepted());
  ASSERT_TRUE(rig.modes.fixed_target().has_value());
  EXPECT_DOUBLE_EQ(rig.modes.fixed_target()->az_deg, 270.0);
}

TEST(StationCommands, TheCommanderIsTheModesOwnWordOnceTheModeChangedByItself) {
  testing::StationRig rig;
  ASSERT_TRUE(rig.commands.jog(program_source(), control::Jog{1, 0}).accepted());
  EXPECT_EQ(rig.commands.commander(), "rotctld 127.0.0.1:50000");
  rig.modes.update(5.0);  // the keep-alive ran out
  EXPECT_NE(rig.commands.commander().find("silent"), std::string::npos);
}

TEST(TargetRequest, TheSatellitePrefixIsParsedOnce) {
  const auto sat = target_from_name("sat:25544");
  ASSERT_TRUE(std::holds_alternative<SatelliteTarget>(sat));
  EXPECT_EQ(std::get<SatelliteTarget>(sat).name_or_norad, "25544");
  EXPECT_TRUE(std::holds_alternative<NamedTarget>(target_from_name("casa")));
  EXPECT_EQ(satellite_display_name("ISS"), "sat:ISS");
}

}  // namespace
}  // namespace azt::app

namespace azt::app {
namespace {

TEST(StationCommands, AMoveBelowFullSpeedIsRecordedWithItsSpeed) {
  testing::StationRig rig;
  const CommandSource pad{CommandSource::Kind::Hands, "game pad"};
  ASSERT_TRUE(rig.commands.jog(pad, control::Jog{1, -1, 0.4, 1.0}).accepted());
  ASSERT_EQ(rig.accepted.size(), 1U);
  EXPECT_EQ(rig.accepted[0],
            "game pad: continuous move az +1 at 40% el -1 (stops after 1 s without traffic)");
  EXPECT_EQ(rig.modes.mode(), control::Mode::Manual);
  EXPECT_EQ(rig.commands.control().holder, "hands");
}

}  // namespace
}  // namespace azt::app
