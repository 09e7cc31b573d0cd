// control::StationSetup: what every backend builds its one StationController from.
#include "azt/control/station_setup.hpp"

#include <gtest/gtest.h>

namespace azt::control {
namespace {

TEST(StationSetup, TheControllerConfigurationCarriesEverySetting) {
  StationSetup s;
  s.az_control.max_rate_deg_s = 3.0;
  s.az_control.lsb_deg = 360.0 / 16384.0;
  s.el_control.window_deg = 0.2;
  s.az_supervisor.stall_window_s = 4.0;
  s.el_supervisor.max_rate_deg_s = 0.8;
  s.az_range = *AzimuthRange::make(-90.0, 450.0);
  s.el_range = *ElevationRange::make(0.0, 180.0);
  s.tick_s = 0.025;
  const StationControlConfig c = s.control_config();
  EXPECT_DOUBLE_EQ(c.az_control.max_rate_deg_s, 3.0);
  EXPECT_DOUBLE_EQ(c.az_control.lsb_deg, 360.0 / 16384.0);
  EXPECT_DOUBLE_EQ(c.el_control.window_deg, 0.2);
  EXPECT_DOUBLE_EQ(c.az_supervisor.stall_window_s, 4.0);
  EXPECT_DOUBLE_EQ(c.el_supervisor.max_rate_deg_s, 0.8);
  EXPECT_DOUBLE_EQ(c.az_range.min_deg, -90.0);
  EXPECT_DOUBLE_EQ(c.el_range.max_deg, 180.0);
  EXPECT_DOUBLE_EQ(c.tick_s, 0.025);
  // Drives and sensors are the backend's to choose: PWM and single-turn by default.
  EXPECT_EQ(c.az_drive.kind, DriveKind::Pwm);
  EXPECT_FALSE(c.az_absolute);
}

}  // namespace
}  // namespace azt::control
