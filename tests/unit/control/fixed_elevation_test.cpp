// A station whose elevation does not move (StationControlConfig::el_fixed_deg): a fixed-elevation
// EME array, or an azimuth-only rotator at 0. Only azimuth is read, driven and supervised; the
// station has no elevation ports at all.

#include <gtest/gtest.h>

#include <memory>

#include "azt/control/ported_station.hpp"
#include "azt/sim/axis_plant.hpp"
#include "azt/sim/reference_station.hpp"
#include "fake_station_ports.hpp"

namespace azt::control {
namespace {

constexpr double kTickS = 0.05;
constexpr double kFixedElDeg = 12.0;

/// The reference station's azimuth around a plant read perfectly each tick, elevation fixed.
struct AzOnlyRig {
  sim::StationSimSetup setup = sim::reference_station(16, 0.1);
  sim::AxisPlant az{setup.plant.az};
  StationController station{config(), AzEl{setup.plant.az.start_deg, 45.0}};
  double t = 0.0;

  [[nodiscard]] StationControlConfig config() const {
    StationControlConfig c = setup.station.control_config();
    c.az_control.lsb_deg = 360.0 / 65536;
    c.el_fixed_deg = kFixedElDeg;
    return c;
  }
  /// Ticks for `seconds`; the elevation "reading" is garbage: a fixed elevation never reads it.
  void run(const Demand& demand, double seconds) {
    for (const double end = t + seconds; t < end; t += kTickS) {
      station.on_encoder_reading(t, wrap_360(az.shaft_deg()), 300.0);
      const Duties d = station.tick(t, demand, AzEl{});
      EXPECT_EQ(d.el, 0.0);
      az.step(d.az, kTickS);
    }
  }
};

TEST(FixedElevation, TracksAzimuthOnlyAndReportsTheFixedAngle) {
  AzOnlyRig rig;
  Demand go;
  go.position = AzEl{rig.setup.plant.az.start_deg + 25.0, 60.0};
  rig.run(go, 90.0);
  const auto sky = rig.station.sky_position(rig.t);
  ASSERT_TRUE(sky.has_value());
  EXPECT_NEAR(sky->az_deg, wrap_360(rig.setup.plant.az.start_deg + 25.0), 0.12);
  EXPECT_DOUBLE_EQ(sky->el_deg, kFixedElDeg);
  EXPECT_DOUBLE_EQ(rig.station.el().mount_deg, kFixedElDeg);
  EXPECT_FALSE(rig.station.faulted());
  EXPECT_EQ(rig.station.starts_el(), 0U);
}

TEST(FixedElevation, AnElevationDirectionTestMovesNothing) {
  AzOnlyRig rig;
  Demand test;
  test.test = AxisTest{false, 1};
  const double before = rig.az.shaft_deg();
  rig.run(test, 5.0);
  EXPECT_DOUBLE_EQ(rig.az.shaft_deg(), before);
  EXPECT_FALSE(rig.station.faulted());
}

TEST(FixedElevation, ElevationLimitSwitchesAndTheEStopLeaveNoElevationFault) {
  AzOnlyRig rig;
  (void)rig.station.set_limits(LimitSwitches{false, false, true, true});
  rig.station.emergency_stop(rig.t);
  EXPECT_TRUE(rig.station.faulted());
  EXPECT_EQ(rig.station.el().fault, FaultKind::None);
  rig.station.clear_faults();
  EXPECT_FALSE(rig.station.faulted());
}

/// The station over its ports, with no elevation drive or sensor.
struct AzOnlyPorts {
  std::shared_ptr<FakeAxis> az = std::make_shared<FakeAxis>();
  std::unique_ptr<PortedStation> station;

  AzOnlyPorts() {
    StationControlConfig c;
    c.tick_s = kTickS;
    c.el_fixed_deg = kFixedElDeg;
    ports::StationPorts p;
    p.drives[0] = std::make_unique<FakeDrive>(az);
    p.sensors[0] = std::make_unique<FakeSensor>(az);
    station = std::make_unique<PortedStation>(c, AzEl{}, PositionCorrections{}, std::move(p));
  }
};

TEST(FixedElevation, APortedStationNeedsNoElevationPorts) {
  AzOnlyPorts rig;
  rig.az->reading_deg = 50.0;
  Demand go;
  go.position = AzEl{100.0, 80.0};
  for (int i = 0; i < 20; ++i) rig.station->tick(i * kTickS, go, AzEl{});
  EXPECT_GT(rig.az->duty, 0.0);
  const auto sky = rig.station->station().sky_position(19 * kTickS);
  ASSERT_TRUE(sky.has_value());
  EXPECT_DOUBLE_EQ(sky->el_deg, kFixedElDeg);
  EXPECT_TRUE(rig.station->faults().empty());
  rig.station->stop_with(1.0, "test");
  EXPECT_EQ(rig.az->duty, 0.0);
  EXPECT_EQ(rig.az->offs, 1);
}

TEST(FixedElevation, ASilentAzimuthSensorStillStopsTheStation) {
  AzOnlyPorts rig;
  rig.az->reading_deg = 50.0;
  Demand go;
  go.position = AzEl{100.0, 10.0};
  rig.station->tick(0.0, go, AzEl{});
  rig.az->reading_deg.reset();
  double t = 0.0;
  for (int i = 1; i < 100; ++i) rig.station->tick(t = i * kTickS, go, AzEl{});
  EXPECT_FALSE(rig.station->station().sky_position(t).has_value());
  EXPECT_EQ(rig.az->duty, 0.0);
}

}  // namespace
}  // namespace azt::control
