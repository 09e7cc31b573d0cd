// The pass planner (issue 7 §2) on synthetic passes of every kind, then the real controller
// through 200 of them on the simulated plant (§4): a 0–450° rotator and a flip mount, 6°/s in
// azimuth and 3°/s in elevation.
#include "azt/track/pass_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "azt/sim/pass_sim.hpp"
#include "azt/sim/reference_station.hpp"

namespace azt::track {
namespace {

MountGeometry overlap_450() {
  MountGeometry m;
  m.az = control::AzimuthRange{0.0, 450.0};
  m.el = control::ElevationRange{0.0, 90.0};
  return m;
}

MountGeometry flip_mount() {
  MountGeometry m;
  m.az = control::AzimuthRange{0.0, 360.0};
  m.el = control::ElevationRange{0.0, 180.0};
  return m;
}

std::vector<SkyPoint> pass(double offset_deg, double nearest_az, bool clockwise,
                           double altitude_km = 500.0) {
  sim::SyntheticPass p;
  p.altitude_km = altitude_km;
  p.offset_deg = offset_deg;
  p.nearest_az_deg = nearest_az;
  p.clockwise = clockwise;
  return sim::synthetic_pass(p);
}

TEST(PassPlan, SyntheticPassesHaveTheirClosedFormHighestPoint) {
  const auto sky = pass(5.0, 30.0, true);
  ASSERT_GT(sky.size(), 100U);
  double top = -90.0;
  for (const auto& s : sky) top = std::max(top, s.el_deg);
  EXPECT_NEAR(top, sim::synthetic_max_el_deg(500.0, 5.0), 0.05);
  EXPECT_NEAR(sky.front().el_deg, 0.0, 0.5);
}

TEST(PassPlan, ANorthCrossingPassUsesTheOverlapInsteadOfUnwinding) {
  // Nearest in the north, moving clockwise: the sky azimuth runs ~280 → 0 → ~80.
  const auto sky = pass(12.0, 0.0, true);
  auto plan = plan_pass(sky, overlap_450(), 270.0);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  EXPECT_FALSE(plan.value().flip);
  const auto& t = plan.value().track;
  for (std::size_t i = 1; i < t.size(); ++i) {
    EXPECT_LT(std::fabs(t[i].az_deg - t[i - 1].az_deg), 10.0) << "a jump at sample " << i;
  }
  EXPECT_GT(t.back().az_deg, 360.0) << "did not run on into the overlap";
  EXPECT_LT(plan.value().max_error_deg, 0.01);
}

TEST(PassPlan, AFlipMountFliesANorthCrossingPassFlipped) {
  const auto sky = pass(12.0, 0.0, true);
  auto plan = plan_pass(sky, flip_mount(), 180.0);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  EXPECT_TRUE(plan.value().flip) << "a 0–360 mount cannot cross north without flipping";
  for (const auto& p : plan.value().track) {
    EXPECT_GE(p.el_deg, 90.0);
    EXPECT_GE(p.az_deg, 0.0);
    EXPECT_LE(p.az_deg, 360.0);
  }
}

TEST(PassPlan, AnOverheadPassLeadsTheKeyholeOnA90DegreeMountAndGoesOverTheTopOnAFlipMount) {
  const auto sky = pass(0.02, 100.0, true);  // highest point 89.7°
  auto plain = plan_pass(sky, overlap_450(), 180.0);
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(plain.value().flip);
  // The 180° azimuth swing takes 30 s at 6°/s, spread around the top where cos(el) is small: an
  // error is accepted (the plant cannot do better), but the mount never lags the whole swing.
  EXPECT_GT(plain.value().max_error_deg, 0.01);
  EXPECT_LT(plain.value().max_error_deg, 10.0);
  for (std::size_t i = 1; i < plain.value().track.size(); ++i) {
    const auto& a = plain.value().track[i - 1];
    const auto& b = plain.value().track[i];
    EXPECT_LE(std::fabs(b.az_deg - a.az_deg), 6.0 * (b.t_s - a.t_s) + 1e-9);
  }
  auto flipped = plan_pass(sky, flip_mount(), 180.0);
  ASSERT_TRUE(flipped.ok());
  EXPECT_TRUE(flipped.value().flip);
  EXPECT_LT(flipped.value().max_error_deg, 1.0) << "over the top, the azimuth barely moves";
  std::printf("[ keyhole  ] 89.7° pass: worst error %.2f° on a 90° mount, %.2f° over the top\n",
              plain.value().max_error_deg, flipped.value().max_error_deg);
}

TEST(PassPlan, APassWiderThanTheTravelWaitsAtTheStopInsteadOfUnwinding) {
  MountGeometry narrow = overlap_450();
  narrow.az = control::AzimuthRange{0.0, 360.0};
  // Crossing north on a 0–360 rotator without a flip: no shift holds it all.
  auto plan = plan_pass(pass(12.0, 0.0, true), narrow, 180.0);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  const auto& t = plan.value().track;
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_GE(t[i].az_deg, 0.0);
    EXPECT_LE(t[i].az_deg, 360.0);
    if (i > 0) {
      EXPECT_LT(std::fabs(t[i].az_deg - t[i - 1].az_deg), 10.0) << "a jump at sample " << i;
    }
  }
  EXPECT_GT(plan.value().max_error_deg, 1.0) << "the part beyond the stop is an accepted error";
  EXPECT_FALSE(plan_pass({SkyPoint{0.0, 1.0, 2.0}}, narrow, 0.0).ok());
  EXPECT_FALSE(plan_pass({SkyPoint{1.0, 1.0, 2.0}, SkyPoint{0.0, 1.0, 2.0}}, narrow, 0.0).ok());
}

TEST(PassPlan, SeparationIsTheGreatCircleAngle) {
  EXPECT_NEAR(separation_deg(0.0, 90.0, 180.0, 89.0), 1.0,
              1e-9);  // azimuth means nothing at zenith
  EXPECT_NEAR(separation_deg(10.0, 0.0, 350.0, 0.0), 20.0, 1e-9);
  const SkyPoint s = mount_to_sky({0.0, 10.0, 120.0});
  EXPECT_DOUBLE_EQ(s.az_deg, 190.0);
  EXPECT_DOUBLE_EQ(s.el_deg, 60.0);
}

/// 200 passes: a third crossing north, a third near the zenith, a third low; random directions.
TEST(PassSimulation, TwoHundredPassesWithoutAnUnwind) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  sim::StationSimSetup setup = sim::reference_station(14, 0.1);
  setup.plant.az.max_rate_deg_s = 6.0;
  setup.plant.el.max_rate_deg_s = 3.0;
  setup.station.az_control.max_rate_deg_s = 6.0;
  setup.station.el_control.max_rate_deg_s = 3.0;
  setup.station.az_supervisor.max_rate_deg_s = 6.0;
  setup.station.el_supervisor.max_rate_deg_s = 3.0;
  int flips = 0;
  double worst_excess = 0.0;
  double worst_travel_over = -1e9;
  for (int i = 0; i < 200; ++i) {
    const double altitude = 400.0 + 500.0 * unit(rng);
    double offset = 0.0;
    double nearest = 360.0 * unit(rng);
    switch (i % 3) {
      case 0:  // north-crossing
        nearest = -20.0 + 40.0 * unit(rng);
        offset = 3.0 + 10.0 * unit(rng);
        break;
      case 1:  // near the zenith
        offset = 1.5 * unit(rng);
        break;
      default:  // low: highest point 2–15°
        offset = 14.0 + 4.0 * unit(rng);
        break;
    }
    const auto sky = pass(offset, nearest, unit(rng) < 0.5, altitude);
    if (sky.size() < 10) continue;
    const MountGeometry mount = i % 2 == 0 ? overlap_450() : flip_mount();
    const control::AzEl start{mount.az.min_deg + (mount.az.max_deg - mount.az.min_deg) * unit(rng),
                              10.0};
    auto r = sim::simulate_pass(sky, mount, setup, start, 120.0);
    ASSERT_TRUE(r.ok()) << "pass " << i << ": " << r.error().message;
    const auto& res = r.value();
    EXPECT_EQ(res.unwinds, 0) << "pass " << i;
    EXPECT_TRUE(res.faults.empty()) << "pass " << i << ": " << res.faults.front();
    EXPECT_LE(res.az_travel_deg, res.pass_span_deg + 10.0) << "pass " << i;
    EXPECT_LE(res.max_excess_deg, 2.0) << "pass " << i << " offset " << offset;
    flips += res.flip ? 1 : 0;
    worst_excess = std::max(worst_excess, res.max_excess_deg);
    worst_travel_over = std::max(worst_travel_over, res.az_travel_deg - res.pass_span_deg);
  }
  std::printf(
      "[ passes   ] 200 passes: %d flown flipped, worst error beyond the plan %.2f°, "
      "worst travel beyond the span %.2f°\n",
      flips, worst_excess, worst_travel_over);
  EXPECT_GT(flips, 10);
}

TEST(MountGeometryOfAStation, TakesTheTravelAndTheMountsRates) {
  control::StationSetup station;
  station.az_range = *control::AzimuthRange::make(0.0, 450.0);
  station.el_range = *control::ElevationRange::make(0.0, 180.0);
  station.az_control.max_rate_deg_s = 4.0;
  station.el_control.max_rate_deg_s = 2.5;
  const MountGeometry m = mount_geometry(station);
  EXPECT_DOUBLE_EQ(m.az.max_deg, 450.0);
  EXPECT_TRUE(m.can_flip());
  EXPECT_DOUBLE_EQ(m.max_az_rate_deg_s, 4.0);
  EXPECT_DOUBLE_EQ(m.max_el_rate_deg_s, 2.5);
}

}  // namespace
}  // namespace azt::track
