// The actuator triangle (control/actuator_geometry.hpp) against the worked example of
// docs/hardware.md ("Linear actuators"): an 18-inch actuator (457.2 mm stroke, 520 mm pin to pin
// retracted) with a = 650 mm, b = 400 mm and θ0 = 48° on a 1.2 m dish's elevation axis. The
// figures below are the page's, worked by hand there with the law of cosines.
#include "azt/control/actuator_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace azt::control {
namespace {

constexpr double kTolDeg = 0.01;  // the page's figures are given to 0.01° or better

ActuatorGeometryConfig worked_example() {
  ActuatorGeometryConfig c;
  c.pivot_to_fixed_mm = 650.0;
  c.pivot_to_moving_mm = 400.0;
  c.offset_deg = 48.0;
  c.retracted_mm = 520.0;
  c.extended_mm = 520.0 + 18 * 25.4;  // an 18-inch stroke
  c.sense = ActuatorSense::ExtendRaises;
  return c;
}

ActuatorGeometry example_geometry() { return ActuatorGeometry::make(worked_example()).value(); }

std::string error_of(const ActuatorGeometryConfig& c) {
  const auto r = ActuatorGeometryConfig::make(c);
  return r ? std::string{} : r.error().message;
}

TEST(ActuatorGeometry, WorkedExampleLengthToAngle) {
  const auto g = example_geometry();
  EXPECT_NEAR(g.angle_deg(520.0).value(), 5.12, kTolDeg);  // retracted: the stow end
  EXPECT_NEAR(g.angle_deg(600.0).value(), 16.67, kTolDeg);
  EXPECT_NEAR(g.angle_deg(748.6).value(), 39.56, kTolDeg);  // mid-stroke
  EXPECT_NEAR(g.angle_deg(800.0).value(), 48.35, kTolDeg);
  EXPECT_NEAR(g.angle_deg(977.2).value(), 87.74, kTolDeg);  // extended
  EXPECT_NEAR(g.min_angle_deg(), 5.12, kTolDeg);
  EXPECT_NEAR(g.max_angle_deg(), 87.74, kTolDeg);
}

TEST(ActuatorGeometry, WorkedExampleAngleToLength) {
  const auto g = example_geometry();
  // 0.01° at ≈ 0.15°/mm is about 0.07 mm; the page gives the lengths to 0.01 mm.
  EXPECT_NEAR(g.length_mm(10.0).value(), 554.02, 0.01);
  EXPECT_NEAR(g.length_mm(30.0).value(), 688.76, 0.01);
  EXPECT_NEAR(g.length_mm(45.0).value(), 780.84, 0.01);
  EXPECT_NEAR(g.length_mm(60.0).value(), 862.08, 0.01);
  EXPECT_NEAR(g.length_mm(80.0).value(), 950.08, 0.01);
}

TEST(ActuatorGeometry, WorkedExampleDegreesPerMillimetre) {
  const auto g = example_geometry();
  EXPECT_NEAR(g.deg_per_mm(520.0), 0.1433, 1e-4);
  EXPECT_NEAR(g.deg_per_mm(748.6), 0.1651, 1e-4);
  EXPECT_NEAR(g.deg_per_mm(977.2), 0.3086, 1e-4);
  // The coarse end is the extended one here: more than twice the degrees per mm of the other.
  EXPECT_NEAR(g.max_deg_per_mm(), 0.3086, 1e-4);
  EXPECT_TRUE(std::isnan(g.deg_per_mm(400.0)));
}

TEST(ActuatorGeometry, DerivativeMatchesFiniteDifferences) {
  const auto g = example_geometry();
  for (double length = 521.0; length < 976.0; length += 25.0) {
    const double step = 1e-3;
    const double numeric =
        (g.angle_deg(length + step).value() - g.angle_deg(length - step).value()) / (2 * step);
    EXPECT_NEAR(g.deg_per_mm(length), numeric, 1e-6) << length;
  }
}

TEST(ActuatorGeometry, RoundTripsOverTheStroke) {
  const auto g = example_geometry();
  std::mt19937 rng(33);
  std::uniform_real_distribution<double> stroke(520.0, 977.2);
  for (int i = 0; i < 1000; ++i) {
    const double length = stroke(rng);
    const double angle = g.angle_deg(length).value();
    EXPECT_NEAR(g.length_mm(angle).value(), length, 1e-9);
  }
  // The ends themselves come back inside the stroke (no refusal for a rounding ulp).
  EXPECT_TRUE(g.angle_deg(g.length_mm(g.min_angle_deg()).value()).ok());
  EXPECT_TRUE(g.angle_deg(g.length_mm(g.max_angle_deg()).value()).ok());
}

TEST(ActuatorGeometry, ExtendLowersMirrorsTheAngle) {
  auto c = worked_example();
  c.sense = ActuatorSense::ExtendLowers;
  c.offset_deg = 140.0;  // θ = 140° − φ: retracted is the high end now
  const auto g = ActuatorGeometry::make(c).value();
  EXPECT_NEAR(g.angle_deg(520.0).value(), 140.0 - 53.1163, 1e-4);
  EXPECT_NEAR(g.angle_deg(977.2).value(), 140.0 - 135.7410, 1e-4);
  EXPECT_LT(g.deg_per_mm(700.0), 0.0);
  EXPECT_NEAR(g.min_angle_deg(), 4.259, 1e-3);
  EXPECT_NEAR(g.max_angle_deg(), 86.884, 1e-3);
  EXPECT_NEAR(g.length_mm(g.angle_deg(700.0).value()).value(), 700.0, 1e-9);
  EXPECT_EQ(to_string(ActuatorSense::ExtendLowers), "extend lowers");
  EXPECT_EQ(to_string(ActuatorSense::ExtendRaises), "extend raises");
  EXPECT_EQ(extension_sign(ActuatorSense::ExtendLowers), -1.0);
  EXPECT_EQ(extension_sign(ActuatorSense::ExtendRaises), 1.0);
}

TEST(ActuatorGeometry, RefusesOutsideTheStroke) {
  const auto g = example_geometry();
  const auto short_read = g.angle_deg(519.0);
  ASSERT_FALSE(short_read.ok());
  EXPECT_EQ(short_read.error().message,
            "actuator length 519.0 mm is outside its stroke 520 to 977.2 mm");
  EXPECT_FALSE(g.angle_deg(978.0).ok());
  EXPECT_FALSE(g.angle_deg(std::numeric_limits<double>::quiet_NaN()).ok());
  const auto zenith = g.length_mm(90.0);
  ASSERT_FALSE(zenith.ok());
  EXPECT_EQ(zenith.error().message,
            "angle 90.00 deg is outside the actuator's range 5.12 to 87.74 deg");
  EXPECT_FALSE(g.length_mm(0.0).ok());
  EXPECT_FALSE(g.length_mm(std::numeric_limits<double>::infinity()).ok());
}

TEST(ActuatorGeometryConfig, ErrorsNameTheField) {
  EXPECT_EQ(error_of(worked_example()), "");
  auto c = worked_example();
  c.pivot_to_fixed_mm = 0.0;
  EXPECT_NE(error_of(c).find("pivot_to_fixed_mm"), std::string::npos);
  c = worked_example();
  c.pivot_to_moving_mm = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of(c).find("pivot_to_moving_mm"), std::string::npos);
  c = worked_example();
  c.offset_deg = 400.0;
  EXPECT_NE(error_of(c).find("offset_deg"), std::string::npos);
  c = worked_example();
  c.extended_mm = c.retracted_mm;
  EXPECT_EQ(error_of(c), "retracted_mm must be below extended_mm");
  c = worked_example();
  c.retracted_mm = 250.0;  // |a − b| = 250: the triangle closes
  EXPECT_EQ(error_of(c),
            "retracted_mm must be above |pivot_to_fixed_mm - pivot_to_moving_mm| = 250 mm, or the "
            "triangle closes");
  c = worked_example();
  c.extended_mm = 1050.0;  // a + b = 1050
  EXPECT_NE(error_of(c).find("extended_mm must be below"), std::string::npos);
  c = worked_example();
  c.retracted_mm = 253.0;  // a triangle, but only 4.4° from a straight line
  EXPECT_EQ(error_of(c),
            "retracted_mm leaves the actuator 4.37 deg from the line of the arm; at least 5 deg "
            "are needed");
  c = worked_example();
  c.extended_mm = 1049.5;  // 3.6° from the other straight line
  EXPECT_NE(error_of(c).find("extended_mm leaves the actuator"), std::string::npos);
}

}  // namespace
}  // namespace azt::control
