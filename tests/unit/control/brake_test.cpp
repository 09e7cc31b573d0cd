// The axis brake (control/brake.hpp): no duty before the brake is off (K3NG #55: a T-2X
// starting before its brake lifted), engage only after the axis has been still, and a new move
// after an engage waits for it. Ticks of 50 ms.
#include "azt/control/brake.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace azt::control {
namespace {

constexpr double kTick = 0.05;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

Brake brake(double release_s = 1.0, double engage_s = 0.5, double idle_s = 2.0) {
  return Brake(BrakeConfig::make({release_s, engage_s, idle_s}).value());
}

TEST(BrakeConfig, ErrorsNameTheField) {
  EXPECT_TRUE(BrakeConfig::make(BrakeConfig{}).ok());
  EXPECT_EQ(BrakeConfig::make(BrakeConfig{0.0, 0.5, 1.0}).error().message,
            "release_s must be above 0 and at most 10 s");
  EXPECT_EQ(BrakeConfig::make(BrakeConfig{1.0, -0.1, 1.0}).error().message,
            "engage_s must be 0 to 10 s");
  EXPECT_EQ(BrakeConfig::make(BrakeConfig{1.0, 0.5, kNan}).error().message,
            "idle_s must be 0 to 600 s");
}

TEST(Brake, SlowReleaseDelaysMotion) {
  auto b = brake(/*release_s=*/1.5);
  EXPECT_FALSE(b.release_output());
  // The controller wants 0.8 from the first tick; the motor gets nothing for 1.5 s (30 ticks).
  int i = 0;
  for (; i < 30; ++i) {
    EXPECT_EQ(b.update(0.8, 100.0 + i * kTick), 0.0) << i;
    EXPECT_TRUE(b.release_output());
    EXPECT_TRUE(b.holding());
    EXPECT_EQ(b.state(), BrakeState::Releasing);
  }
  EXPECT_EQ(b.update(0.8, 100.0 + i * kTick), 0.8);  // 1.5 s after the release began
  EXPECT_EQ(b.state(), BrakeState::Released);
  EXPECT_FALSE(b.holding());
}

/// Ticks on from tick `i` (time i·kTick) with `duty` wanted until the brake is in `state`:
/// returns that tick (-1 if not within 1000) and leaves `i` at the tick after it.
int tick_reaching(Brake& b, BrakeState state, double duty, int& i) {
  for (const int end = i + 1000; i < end; ++i) {
    b.update(duty, i * kTick);
    if (b.state() == state) return i++;
  }
  return -1;
}

TEST(Brake, EngagesOnlyAfterTheAxisWasStillForIdleS) {
  auto b = brake(0.5, 0.5, 2.0);
  int i = 0;
  ASSERT_EQ(tick_reaching(b, BrakeState::Released, 0.5, i), 10);  // 0.5 s
  // A pause shorter than idle_s keeps the brake off: no brake cycle between tracking moves.
  for (const int end = i + 20; i < end; ++i) EXPECT_EQ(b.update(0.0, i * kTick), 0.0);
  EXPECT_EQ(b.state(), BrakeState::Idle);
  EXPECT_TRUE(b.release_output());
  EXPECT_EQ(b.update(0.4, i++ * kTick), 0.4);  // resumes at once: the brake is still off
  const int stopped = i;
  // 2 s (40 ticks) of stillness, then the brake is applied; it holds 0.5 s later.
  const int engaging = tick_reaching(b, BrakeState::Engaging, 0.0, i);
  EXPECT_EQ(engaging - stopped, 40);
  EXPECT_FALSE(b.release_output());
  EXPECT_EQ(b.engagements(), 1U);
  EXPECT_EQ(to_string(b.state()), "engaging");
  EXPECT_EQ(tick_reaching(b, BrakeState::Engaged, 0.0, i) - engaging, 10);
}

TEST(Brake, AMoveDuringTheEngageWaitsForItThenReleasesFully) {
  auto b = brake(1.0, 0.5, 0.0);
  int i = 0;
  const int released = tick_reaching(b, BrakeState::Released, 1.0, i);
  int k = tick_reaching(b, BrakeState::Engaging, 0.0, i);
  ASSERT_EQ(k - released, 2);  // Idle on the first still tick, engaging on the next (idle_s 0)
  const int engage_began = k;
  while (b.update(1.0, ++k * kTick) == 0.0) {
  }
  // 0.5 s to engage, then the full 1 s release: no shortcut through a half-applied brake.
  EXPECT_EQ(k - engage_began, 30);
}

TEST(Brake, HaltAppliesAtOnce) {
  auto b = brake(0.5, 0.5, 5.0);
  int i = 0;
  tick_reaching(b, BrakeState::Released, 1.0, i);
  b.halt(i * kTick);
  EXPECT_FALSE(b.release_output());
  EXPECT_EQ(b.update(1.0, ++i * kTick), 0.0);
  EXPECT_EQ(b.state(), BrakeState::Engaging);
}

TEST(Brake, HostileInputsApplyTheBrake) {
  auto b = brake(0.5, 0.5, 5.0);
  int i = 0;
  tick_reaching(b, BrakeState::Released, 1.0, i);
  EXPECT_EQ(b.update(kNan, ++i * kTick), 0.0);
  EXPECT_FALSE(b.release_output());
  auto c = brake(0.5, 0.5, 5.0);
  i = 0;
  tick_reaching(c, BrakeState::Released, 1.0, i);
  const double t = i * kTick;
  EXPECT_EQ(c.update(1.0, t - 1.0), 0.0);  // time went backwards
  EXPECT_FALSE(c.release_output());
  // The engage runs from the latest time seen, not from the earlier one.
  EXPECT_EQ(c.update(1.0, t + 0.4), 0.0);
  EXPECT_EQ(c.state(), BrakeState::Engaging);
}

TEST(Brake, NeverADutyWhileNotFullyReleased) {
  // Random wishes, pauses, halts and tick lengths: whenever the duty leaving the brake is not
  // zero, the brake has been released (output on) for at least release_s without a break.
  std::mt19937 rng(55);
  std::uniform_real_distribution<double> duty(-1.0, 1.0);
  std::uniform_real_distribution<double> dt(0.01, 0.2);
  std::uniform_int_distribution<int> pick(0, 9);
  auto b = brake(0.7, 0.3, 0.5);
  double t = 0.0;
  double output_on_since = -1.0;
  int moving_ticks = 0;
  for (int i = 0; i < 20000; ++i) {
    t += dt(rng);
    const int what = pick(rng);
    if (what == 0) b.halt(t);
    const double wanted = what < 4 ? 0.0 : duty(rng);
    const double out = b.update(wanted, t);
    if (!b.release_output()) {
      output_on_since = -1.0;
    } else if (output_on_since < 0.0) {
      output_on_since = t;
    }
    if (out != 0.0) {
      ++moving_ticks;
      ASSERT_GE(output_on_since, 0.0) << i;
      ASSERT_GE(t - output_on_since, 0.7 - 1e-9) << i;
      ASSERT_EQ(b.state(), BrakeState::Released);
    }
  }
  EXPECT_GT(moving_ticks, 1000);  // the property was exercised, not vacuous
}

}  // namespace
}  // namespace azt::control
