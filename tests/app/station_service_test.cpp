// StationService: what PC programs' requests do to the station's modes (issue 4 §2).
#include "station_service.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

namespace azt::app {
namespace {

using proto::ServiceStatus;

/// An antenna standing at az 100°, el 20°, with faults the test sets.
class StandingAntenna final : public AntennaBackend {
 public:
  void tick(double /*now_s*/, const control::Demand& /*demand*/,
            const control::AzEl& /*rate*/) override {}
  [[nodiscard]] std::optional<proto::PositionReport> position(double /*now_s*/) const override {
    proto::PositionReport r;
    r.az_deg = 100.0;
    r.el_deg = 20.0;
    r.az_mount_deg = 100.0;
    r.fault = !faults_.empty();
    return r;
  }
  void stop_now(double /*now_s*/) override {}
  [[nodiscard]] std::vector<std::string> faults() const override { return faults_; }
  void clear_faults() override { faults_.clear(); }
  bool set_corrections(const control::PositionCorrections& /*corrections*/) override {
    return false;
  }
  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override {
    return std::nullopt;
  }
  [[nodiscard]] std::string describe() const override { return "standing antenna"; }

  std::vector<std::string> faults_;
};

struct Rig {
  std::array<control::ParkSlot, control::ModeController::kParkSlots> slots{{
      {"park", {180.0, 0.0}},
      {"stow", {180.0, 90.0}},
      {"north", {0.0, 0.0}},
      {"service", {90.0, 0.0}},
  }};
  control::ModeController modes{slots, control::OutOfRangePolicy::Hold, 0.0};
  StandingAntenna antenna;
  double now_s = 0.0;
  StationService service{modes,
                         antenna,
                         proto::TargetLimits{},
                         control::ElevationRange{0.0, 90.0},
                         "test station",
                         [this] { return now_s; },
                         [](const std::string&) {}};
};

TEST(StationService, APositionTargetPutsTheStationInExtMode) {
  Rig rig;
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Ok);
  EXPECT_EQ(rig.modes.mode(), control::Mode::External);
  ASSERT_TRUE(rig.modes.fixed_target().has_value());
  EXPECT_DOUBLE_EQ(rig.modes.fixed_target()->az_deg, 120.0);
}

TEST(StationService, ALatchedFaultRefusesEveryMotionRequest) {
  Rig rig;
  rig.antenna.faults_ = {"az: stall: driven for 2 s but moved less than 0.5 deg"};
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Rejected);
  EXPECT_EQ(rig.service.goto_axis("rotctld a", proto::Axis::Az, 120.0), ServiceStatus::Rejected);
  EXPECT_EQ(rig.service.move("rotctld a", proto::AxisMotion{1, 0}), ServiceStatus::Rejected);
  EXPECT_EQ(rig.service.park("rotctld a"), ServiceStatus::Rejected);
  EXPECT_NE(rig.modes.mode(), control::Mode::External);
  ASSERT_TRUE(rig.service.position().has_value());  // the position is still reported
  EXPECT_TRUE(rig.service.position()->fault);
  rig.antenna.clear_faults();  // an operator's decision
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 30.0), ServiceStatus::Ok);
}

TEST(StationService, InvalidTargetsAreInvalidNotRejected) {
  Rig rig;
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 95.0), ServiceStatus::Invalid);
  rig.antenna.faults_ = {"el: runaway"};
  EXPECT_EQ(rig.service.goto_position("rotctld a", 120.0, 95.0), ServiceStatus::Invalid);
}

}  // namespace
}  // namespace azt::app
