// Counts to angle (control/pulse_scale.hpp): counts per degree on a rotator, counts per mm
// through the worked example's actuator triangle (docs/hardware.md, "Linear actuators").
#include "azt/control/pulse_scale.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace azt::control {
namespace {

ActuatorGeometry worked_example(ActuatorSense sense = ActuatorSense::ExtendRaises) {
  ActuatorGeometryConfig c;
  c.pivot_to_fixed_mm = 650.0;
  c.pivot_to_moving_mm = 400.0;
  c.offset_deg = sense == ActuatorSense::ExtendRaises ? 48.0 : 140.0;
  c.retracted_mm = 520.0;
  c.extended_mm = 977.2;
  c.sense = sense;
  return ActuatorGeometry::make(c).value();
}

PulseScaleConfig per_mm(double counts_per_mm, double home_mm) {
  return PulseScaleConfig{PulseUnit::Millimetres, counts_per_mm, home_mm};
}

TEST(PulseScale, CountsPerDegree) {
  const auto s = PulseScale::make({PulseUnit::Degrees, 2.0, -5.0}).value();
  EXPECT_DOUBLE_EQ(s.angle_deg(0).value(), -5.0);  // the home switch's angle
  EXPECT_DOUBLE_EQ(s.angle_deg(730).value(), 360.0);
  EXPECT_DOUBLE_EQ(s.angle_deg(-10).value(), -10.0);
  EXPECT_DOUBLE_EQ(s.counts_at(90.0).value(), 190.0);
  EXPECT_DOUBLE_EQ(s.deg_per_count(12), 0.5);
  EXPECT_DOUBLE_EQ(s.max_deg_per_count(), 0.5);
  EXPECT_FALSE(s.counts_at(NAN).ok());
  EXPECT_EQ(to_string(PulseUnit::Degrees), "degrees");
}

TEST(PulseScale, CountsPerMillimetreThroughTheTriangle) {
  // One reed pulse per mm, home switch 2 mm off the retracted end.
  const auto s = PulseScale::make(per_mm(1.0, 522.0), worked_example()).value();
  const auto g = worked_example();
  EXPECT_DOUBLE_EQ(s.angle_deg(0).value(), g.angle_deg(522.0).value());
  EXPECT_DOUBLE_EQ(s.angle_deg(226).value(), g.angle_deg(748.0).value());
  EXPECT_NEAR(s.counts_at(30.0).value(), 688.757 - 522.0, 1e-3);
  // Degrees per pulse grow along the stroke: 0.143 at the bottom, 0.309 at the top.
  EXPECT_NEAR(s.deg_per_count(0), 0.1433, 1e-3);
  EXPECT_NEAR(s.max_deg_per_count(), 0.3086, 1e-4);
  const auto beyond = s.angle_deg(500);  // 1022 mm: longer than the actuator gets
  ASSERT_FALSE(beyond.ok());
  EXPECT_EQ(beyond.error().message,
            "count 500 from home: actuator length 1022.0 mm is outside its stroke 520 to 977.2 mm");
  EXPECT_FALSE(s.angle_deg(-3).ok());  // 519 mm
  EXPECT_TRUE(std::isnan(s.deg_per_count(-3)));
}

TEST(PulseScale, ExtendLowersCountsRiseAsTheActuatorShortens) {
  // Forward (increasing angle) retracts this actuator: the count rises as the length falls.
  const auto s =
      PulseScale::make(per_mm(2.0, 975.0), worked_example(ActuatorSense::ExtendLowers)).value();
  const auto g = worked_example(ActuatorSense::ExtendLowers);
  EXPECT_DOUBLE_EQ(s.angle_deg(0).value(), g.angle_deg(975.0).value());
  EXPECT_DOUBLE_EQ(s.angle_deg(100).value(), g.angle_deg(925.0).value());
  EXPECT_GT(s.angle_deg(100).value(), s.angle_deg(0).value());
  EXPECT_NEAR(s.counts_at(s.angle_deg(100).value()).value(), 100.0, 1e-6);
}

TEST(PulseScale, ValidationNamesTheField) {
  auto err = [](const PulseScaleConfig& c, std::optional<ActuatorGeometry> g = std::nullopt) {
    const auto r = PulseScale::make(c, g);
    return r ? std::string{} : r.error().message;
  };
  EXPECT_EQ(err({PulseUnit::Degrees, 0.0, 0.0}), "counts_per_unit must be above 0 and at most 1e6");
  EXPECT_EQ(err({PulseUnit::Degrees, 1.0, INFINITY}), "home_value must be finite");
  EXPECT_EQ(err(per_mm(1.0, 600.0)), "counts per millimetre need the actuator geometry");
  EXPECT_EQ(err({PulseUnit::Degrees, 1.0, 0.0}, worked_example()),
            "an actuator geometry needs counts per millimetre, not degrees");
  EXPECT_EQ(err(per_mm(1.0, 400.0), worked_example()),
            "home_value 400 mm is outside the actuator's stroke 520 to 977.2 mm");
}

}  // namespace
}  // namespace azt::control
