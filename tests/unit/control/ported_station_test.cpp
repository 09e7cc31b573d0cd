#include "azt/control/ported_station.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "fake_station_ports.hpp"

namespace azt::control {
namespace {

constexpr double kTickS = 0.05;

struct Station {
  std::array<std::shared_ptr<FakeAxis>, 3> axes{
      std::make_shared<FakeAxis>(), std::make_shared<FakeAxis>(), std::make_shared<FakeAxis>()};
  std::unique_ptr<PortedStation> station;
  double t = 0.0;

  explicit Station(bool with_pol_config, bool with_pol_ports = true) {
    StationControlConfig c;
    c.tick_s = kTickS;
    if (with_pol_config) {
      PolAxisConfig pol;
      pol.control.lsb_deg = 360.0 / 4096;
      pol.travel = PolTravel{-95.0, 95.0};
      c.pol = pol;
    }
    ports::StationPorts p;
    for (std::size_t i = 0; i < 2; ++i) {
      p.drives.at(i) = std::make_unique<FakeDrive>(axes.at(i));
      p.sensors.at(i) = std::make_unique<FakeSensor>(axes.at(i));
    }
    if (with_pol_ports) {
      p.pol_drive = std::make_unique<FakeDrive>(axes[2]);
      p.pol_sensor = std::make_unique<FakeSensor>(axes[2]);
    }
    station = std::make_unique<PortedStation>(c, AzEl{}, PositionCorrections{}, std::move(p));
  }
  FakeAxis& pol() { return *axes[2]; }
  /// Ticks for `seconds`, holding az/el, asking the pol axis for `feed_deg`.
  void run(std::optional<double> feed_deg, double seconds) {
    for (const double end = t + seconds; t < end - 1e-9; t += kTickS) {
      station->tick(t, Demand{}, AzEl{}, PolDemand{feed_deg, 0.0});
    }
  }
  [[nodiscard]] bool faults_contain(std::string_view text) const {
    const auto f = station->faults();
    return std::any_of(f.begin(), f.end(),
                       [&](const std::string& s) { return s.find(text) != std::string::npos; });
  }
};

TEST(PortedStationPol, WithoutPolPortsOrSettingsThereIsNoPolAxis) {
  Station no_settings(false);
  EXPECT_EQ(no_settings.station->pol(), nullptr);
  no_settings.run(40.0, 0.5);
  EXPECT_EQ(no_settings.pol().duty, 0.0);  // its ports are never driven
  Station no_ports(true, false);
  EXPECT_EQ(no_ports.station->pol(), nullptr);
  no_ports.run(40.0, 0.5);
}

TEST(PortedStationPol, DrivesTheFeedTowardsItsAngleWhileAzAndElHold) {
  Station s(true);
  s.pol().reading_deg = 10.0;
  s.run(40.0, 0.5);
  ASSERT_NE(s.station->pol(), nullptr);
  EXPECT_EQ(s.station->pol()->target_mount_deg(), 40.0);
  EXPECT_GT(s.pol().duty, 0.0);
  EXPECT_EQ(s.axes[0]->duty, 0.0);
  EXPECT_EQ(s.axes[1]->duty, 0.0);
}

TEST(PortedStationPol, TakesTheEquivalentAngleInsideTheTravel) {
  Station s(true);
  s.pol().reading_deg = 80.0;
  s.run(-80.0, 0.3);  // 100 lies beyond the travel's 95: the feed turns back to −80
  EXPECT_EQ(s.station->pol()->target_mount_deg(), -80.0);
  EXPECT_LT(s.pol().duty, 0.0);
  Station fresh(true);
  fresh.pol().reading_deg = 350.0;  // a single-turn sensor's −10
  fresh.run(-80.0, 0.3);
  EXPECT_NEAR(fresh.station->pol()->axis().mount_deg(), -10.0, 1e-9);
}

TEST(PortedStationPol, NoFeedAngleHoldsTheAxis) {
  Station s(true);
  s.pol().reading_deg = 10.0;
  s.run(std::nullopt, 0.5);
  EXPECT_FALSE(s.station->pol()->target_mount_deg().has_value());
  EXPECT_EQ(s.pol().duty, 0.0);
}

TEST(PortedStationPol, ASilentPolSensorStopsThePolMotor) {
  Station s(true);
  s.pol().reading_deg = 10.0;
  s.run(40.0, 0.5);
  ASSERT_GT(s.pol().duty, 0.0);
  s.pol().reading_deg.reset();  // nothing new from now on
  s.run(40.0, 1.0);
  EXPECT_EQ(s.pol().duty, 0.0);
}

TEST(PortedStationPol, APolSensorErrorIsReportedAndStopsThePolMotor) {
  Station s(true);
  s.pol().reading_deg = 10.0;
  s.run(40.0, 0.5);
  s.pol().read_error = "pol encoder: bus error";
  s.run(40.0, 1.0);
  EXPECT_EQ(s.pol().duty, 0.0);
  EXPECT_TRUE(s.faults_contain("pol encoder: bus error"));
}

TEST(PortedStationPol, TheEmergencyStopStopsAndLatchesThePolAxisToo) {
  Station s(true);
  s.pol().reading_deg = 10.0;
  s.run(40.0, 0.5);
  ASSERT_GT(s.pol().duty, 0.0);
  s.station->stop_with(s.t, "emergency stop input active");
  EXPECT_EQ(s.pol().duty, 0.0);
  EXPECT_GE(s.pol().offs, 1);
  EXPECT_TRUE(s.faults_contain("pol: "));
  s.run(40.0, 0.5);
  EXPECT_EQ(s.pol().duty, 0.0);  // latched until cleared
  s.station->clear_faults();
  s.run(40.0, 0.5);
  EXPECT_GT(s.pol().duty, 0.0);
}

TEST(PortedStationPol, APolDriveWriteErrorStopsTheWholeStation) {
  Station s(true);
  s.pol().reading_deg = 10.0;
  s.pol().write_error = "pol PWM: write failed";
  s.run(40.0, 0.1);
  EXPECT_TRUE(s.faults_contain("pol drive: pol PWM: write failed"));
  EXPECT_TRUE(s.station->station().faulted());
  EXPECT_GE(s.axes[0]->offs, 1);
}

TEST(PortedStationPol, ATrippedPolSwitchStopsTheDriveIntoIt) {
  Station s(true);
  s.pol().reading_deg = 10.0;
  s.run(40.0, 0.5);
  ASSERT_GT(s.pol().duty, 0.0);
  s.station->set_pol_limits(s.t, LimitPair{false, true});
  EXPECT_EQ(s.pol().duty, 0.0);  // at once, not at the next tick
  s.run(40.0, 0.5);
  EXPECT_EQ(s.pol().duty, 0.0);
  s.run(-40.0, 0.5);  // away from it is allowed
  EXPECT_LT(s.pol().duty, 0.0);
}

// The console's direction test of the pol axis: open loop, slowly, the way asked, whatever the
// feed angle; and a tripped switch still stops it.
TEST(PortedStationPol, ADirectionTestDrivesThePolAxisSlowlyTheWayAsked) {
  Station s(true);
  s.pol().reading_deg = 10.0;
  for (int i = 0; i < 10; ++i, s.t += kTickS)
    s.station->tick(s.t, Demand{}, AzEl{}, PolDemand{-40.0, 0.0, +1});
  EXPECT_GT(s.pol().duty, 0.0);
  EXPECT_LT(s.pol().duty, 0.5);
  EXPECT_EQ(s.axes[0]->duty, 0.0);
  s.station->set_pol_limits(s.t, LimitPair{false, true});
  s.station->tick(s.t, Demand{}, AzEl{}, PolDemand{std::nullopt, 0.0, +1});
  EXPECT_EQ(s.pol().duty, 0.0);
}

}  // namespace
}  // namespace azt::control
