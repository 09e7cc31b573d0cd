// The simulated brake (sim/brake_plant.hpp) alone, then between the core's Brake and the
// reference axis plant: a brake slower to release than to engage delays the motion by the
// configured release time and the motor never pulls against it; configured too short, the
// plant records the pull (so the clean run's zero means something).
#include "azt/sim/brake_plant.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>

#include "azt/control/axis_controller.hpp"
#include "azt/control/brake.hpp"
#include "azt/sim/axis_plant.hpp"

namespace azt::sim {
namespace {

constexpr double kTick = 0.02;

TEST(BrakePlant, ValidatesAndHoldsUntilFullyReleased) {
  EXPECT_EQ((BrakePlantParams{0.0, 0.3}).validate().error().message,
            "release_s must be above 0 and at most 60 s");
  EXPECT_EQ((BrakePlantParams{1.0, NAN}).validate().error().message,
            "engage_s must be above 0 and at most 60 s");
  BrakePlant b(BrakePlantParams{1.0, 0.25});
  int held_steps = 0;
  while (b.step(true, 0.7, kTick) == 0.0) ++held_steps;
  EXPECT_NEAR(held_steps * kTick, 1.0, 2 * kTick);  // pulled against it all that time
  EXPECT_EQ(b.pulled_against_steps(), static_cast<std::uint64_t>(held_steps));
  EXPECT_NEAR(b.pulled_against_s(), held_steps * kTick, 1e-9);
  // De-energised, it holds again after one step: partly applied is applied.
  EXPECT_EQ(b.step(false, 0.7, kTick), 0.0);
  EXPECT_FALSE(b.released());
  for (int i = 0; i < 20; ++i) b.step(false, 0.0, kTick);
  EXPECT_EQ(b.progress(), 0.0);
}

control::AxisControlConfig controller_config() {
  control::AxisControlConfig c;
  c.min_duty = 0.1;  // the plant's stiction: without it the final approach never arrives
  return control::AxisControlConfig::make(c).value();
}

struct BrakedAxis {
  control::AxisController controller{controller_config()};
  control::Brake brake;
  BrakePlant brake_plant{BrakePlantParams{1.2, 0.3}};  // slow to release
  AxisPlant axis{AxisParams{1.5, 0.3, 0.0, 0.1, 12, 10.0, 0.0, 360.0}};
  double now_s = 0.0;
  int ticks_driven_while_holding = 0;

  explicit BrakedAxis(double release_s)
      : brake(control::BrakeConfig::make({release_s, 0.5, 1.0}).value()) {}

  void tick(double target_deg) {
    const double wanted = controller.update(target_deg, axis.shaft_deg(), 0.0, kTick);
    const double duty = brake.update(wanted, now_s);
    if (brake.holding()) controller.halt();  // the soft start begins at the release
    if (duty != 0.0 && !brake_plant.released()) ++ticks_driven_while_holding;
    axis.step(brake_plant.step(brake.release_output(), duty, kTick), kTick);
    now_s += kTick;
  }
};

TEST(BrakedAxis, SlowBrakeDelaysMotionAndIsNeverPulledAgainst) {
  BrakedAxis a(/*release_s=*/1.5);  // configured above the brake's real 1.2 s
  std::optional<double> first_move_s;
  // To 30°, until the brake begins to engage after the axis came to rest.
  while (a.brake.state() != control::BrakeState::Engaging && a.now_s < 60.0) {
    a.tick(30.0);
    if (!first_move_s && a.axis.shaft_deg() != 10.0) first_move_s = a.now_s;
  }
  ASSERT_TRUE(first_move_s.has_value());
  EXPECT_GE(*first_move_s, 1.5);  // nothing moved before the configured release time
  // … and it moves soon after: the soft start (ramp_s 1 s) takes the duty past the motor's
  // stiction (0.1) in 0.1 s, plus the motor's lag.
  EXPECT_LT(*first_move_s, 1.5 + 0.2);
  ASSERT_EQ(a.brake.state(), control::BrakeState::Engaging);
  EXPECT_NEAR(a.axis.shaft_deg(), 30.0, 0.2);
  // A second move while the brake engages: it waits for the engage, then releases fully.
  const double engaging_s = a.now_s;
  const double rest_deg = a.axis.shaft_deg();
  std::optional<double> second_move_s;
  while (a.now_s < engaging_s + 60.0) {
    a.tick(10.0);
    // Moved towards 10° by more than the last of the first move's coast could account for.
    if (!second_move_s && a.axis.shaft_deg() < rest_deg - 0.05) second_move_s = a.now_s;
  }
  ASSERT_TRUE(second_move_s.has_value());
  EXPECT_GE(*second_move_s - engaging_s, 0.5 + 1.5);  // engage_s, then release_s
  EXPECT_NEAR(a.axis.shaft_deg(), 10.0, 0.2);
  EXPECT_EQ(a.ticks_driven_while_holding, 0);
  EXPECT_EQ(a.brake_plant.pulled_against_s(), 0.0);
  EXPECT_EQ(a.brake.engagements(), 2U);
  EXPECT_FALSE(a.brake.release_output());  // applied again after the axis came to rest
}

TEST(BrakedAxis, ReleaseTimeShorterThanTheBrakeIsCaughtByThePlant) {
  BrakedAxis a(/*release_s=*/0.5);  // misconfigured: the brake needs 1.2 s
  while (a.now_s < 5.0) a.tick(30.0);
  // Driven from 0.5 s until the brake came off at 1.2 s.
  EXPECT_NEAR(a.brake_plant.pulled_against_s(), 0.7, 2 * kTick);
  EXPECT_GT(a.ticks_driven_while_holding, 30);
}

}  // namespace
}  // namespace azt::sim
