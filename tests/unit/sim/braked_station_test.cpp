// The daemon's station (PortedStation over StationController) on the simulated plants with a
// brake and a motor that heats: the brake's line and the motor's temperature travel through the
// station's ports as on a real station.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "azt/control/ported_station.hpp"
#include "azt/sim/reference_station.hpp"
#include "azt/sim/simulated_station.hpp"
#include "azt/sim/station_sim.hpp"

namespace azt::sim {
namespace {

constexpr double kTickS = 0.05;

struct BrakedStation {
  std::shared_ptr<const PlantRig> rig;
  std::unique_ptr<control::PortedStation> station;
  double t = 0.0;

  explicit BrakedStation(double start_c) {
    StationSimSetup setup = reference_station(12, 0.2);
    setup.plant.brakes[0] = BrakePlantParams{1.2, 0.3};  // the real brake: 1.2 s to lift
    setup.plant.thermal[0] = MotorThermalParams{20.0, 80.0, 30.0, start_c};
    control::StationControlConfig c = station_control_config(setup);
    c.az_drive.brake = control::BrakeConfig{1.5, 0.5, 1.0};  // configured above the real 1.2 s
    control::MotorTripsConfig trips;
    trips.axis = "az";
    trips.temperature_limit_c = 75.0;
    trips.temperature_hysteresis_c = 5.0;
    c.az_drive.trips = trips;
    SimulatedStation sim = make_simulated_station(setup.plant, make_model_hub(setup.plant));
    rig = sim.rig;
    station = std::make_unique<control::PortedStation>(
        c, control::AzEl{setup.plant.az.start_deg, setup.plant.el.start_deg},
        setup.station.corrections, std::move(sim.ports));
  }
  void tick(double az_deg) {
    control::Demand d;
    d.position = control::AzEl{az_deg, 10.0};
    station->tick(t, d, control::AzEl{});
    t += kTickS;
  }
  [[nodiscard]] double az_deg() const { return rig->plants().az().shaft_deg(); }
  [[nodiscard]] bool faults_contain(std::string_view text) const {
    const auto f = station->faults();
    return std::any_of(f.begin(), f.end(),
                       [&](const std::string& s) { return s.find(text) != std::string::npos; });
  }
};

TEST(BrakedStation, ASlowBrakeDelaysMotionAndTheMotorNeverPullsAgainstIt) {
  BrakedStation s(20.0);
  const double start = s.az_deg();
  std::optional<double> released_from_s;
  std::optional<double> first_duty_s;
  std::optional<double> first_move_s;
  for (int i = 0; i < 1200; ++i) {  // 60 s: there, at rest, and braked again
    const double t = s.t;
    s.tick(200.0);
    const control::AxisStatus az = s.station->station().az();
    if (!released_from_s && az.brake_release) released_from_s = t;
    if (!first_duty_s && az.duty != 0.0) first_duty_s = t;
    if (!first_move_s && std::fabs(s.az_deg() - start) > 1e-6) first_move_s = t;
  }
  ASSERT_TRUE(released_from_s && first_duty_s && first_move_s);
  EXPECT_LE(*released_from_s, 0.2);  // once the first hub frames are in
  EXPECT_NEAR(*first_duty_s - *released_from_s, 1.5, kTickS + 1e-9);
  // The shaft follows once the soft start passes the stiction and the play is taken up.
  EXPECT_GT(*first_move_s, *first_duty_s);
  EXPECT_LT(*first_move_s, *first_duty_s + 0.6);
  EXPECT_NEAR(s.az_deg(), 200.0, 0.3);
  const BrakePlant* brake = s.rig->brake(0);
  ASSERT_NE(brake, nullptr);
  EXPECT_EQ(brake->pulled_against_steps(), 0U);
  EXPECT_EQ(brake->progress(), 0.0) << "applied again once the axis was at rest";
  EXPECT_TRUE(s.station->faults().empty()) << s.station->faults().front();
  EXPECT_TRUE(s.station->station().az().brake == control::BrakeState::Engaged);
}

TEST(BrakedStation, AMotorThatOverheatsTripsLatchesAndIsResetOnlyOnceCool) {
  BrakedStation s(60.0);
  bool tripped = false;
  for (int i = 0; i < 1200 && !tripped; ++i) {  // a long move at full duty heats the motor
    s.tick(350.0);
    tripped = s.station->station().az().fault == control::FaultKind::MotorTrip;
  }
  ASSERT_TRUE(tripped) << s.station->station().az().reason;
  EXPECT_TRUE(s.faults_contain("az: motor_trip: motor temperature 75."));
  EXPECT_EQ(s.station->station().az().duty, 0.0);
  EXPECT_FALSE(s.station->station().az().brake_release);
  EXPECT_LT(s.az_deg(), 340.0);
  // Latched while it cools: still asked to go on, it does not move.
  const double stopped_at = s.az_deg();
  for (int i = 0; i < 40; ++i) s.tick(350.0);
  s.station->clear_faults();
  EXPECT_TRUE(s.faults_contain("is not yet below 70 °C"));
  for (int i = 0; i < 600; ++i) s.tick(350.0);  // 30 s: τ is 30 s, it cools well below 70 °C
  EXPECT_NEAR(s.az_deg(), stopped_at, 0.6);     // the coast as it stopped (τ 0.3 s), no more
  s.station->clear_faults();
  EXPECT_TRUE(s.station->faults().empty()) << s.station->faults().front();
  for (int i = 0; i < 100; ++i) s.tick(350.0);
  EXPECT_GT(s.az_deg(), stopped_at + 1.0);
  EXPECT_EQ(s.rig->brake(0)->pulled_against_steps(), 0U);
}

}  // namespace
}  // namespace azt::sim
