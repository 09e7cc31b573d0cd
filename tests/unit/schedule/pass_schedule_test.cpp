// The satellite schedule's plan (docs/satellites.md "The schedule"): priorities, the two
// preemption rules, the minimum elevation, pre-positions timed by the slew, parking and the
// motors' power when idle. Times are seconds from an arbitrary origin.
#include "azt/schedule/pass_schedule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace azt::schedule {
namespace {

ScheduledPass pass(std::size_t priority, double aos_s, double los_s, double max_el_deg = 40.0,
                   control::AzEl aos_sky = {90.0, 0.0}, control::AzEl los_sky = {270.0, 0.0}) {
  return ScheduledPass{priority, aos_s, los_s, max_el_deg, aos_sky, los_sky, {}};
}

std::vector<Priority> list(std::vector<Preempt> rules) {
  std::vector<Priority> out;
  for (std::size_t i = 0; i < rules.size(); ++i) {
    out.push_back({"sat" + std::to_string(i), std::to_string(25544 + i), 0.0, rules[i]});
  }
  return out;
}

ScheduleRules rules() {
  ScheduleRules r;
  r.idle_park_s = 600.0;
  r.park_sky = {180.0, 0.0};
  r.az_rate_deg_s = 2.0;
  r.el_rate_deg_s = 1.0;
  r.settle_s = 5.0;
  return r;
}

std::vector<PlanStep> of_kind(const std::vector<PlanStep>& plan, StepKind kind) {
  std::vector<PlanStep> out;
  for (const auto& s : plan) {
    if (s.kind == kind) out.push_back(s);
  }
  return out;
}

TEST(PassSchedule, SlewTimeIsTheSlowerAxisTheShortWayRoundPlusTheSettle) {
  const ScheduleRules r = rules();
  EXPECT_DOUBLE_EQ(slew_time_s({350.0, 10.0}, {10.0, 10.0}, r), 20.0 / 2.0 + 5.0);
  EXPECT_DOUBLE_EQ(slew_time_s({0.0, 0.0}, {30.0, 60.0}, r), 60.0 / 1.0 + 5.0);
}

TEST(PassSchedule, EachPassIsPrepositionedJustInTimeThenTracked) {
  // Start at az 180: 90° to the first AOS at 2°/s is 45 s, plus 5 s settle.
  const auto plan =
      plan_schedule(list({Preempt::TakeOver}), {pass(0, 100.0, 500.0), pass(0, 700.0, 1100.0)},
                    rules(), 0.0, 1200.0, {180.0, 0.0});
  ASSERT_EQ(plan.size(), 4U);
  EXPECT_EQ(plan[0].kind, StepKind::Preposition);
  EXPECT_DOUBLE_EQ(plan[0].from_s, 50.0);
  EXPECT_DOUBLE_EQ(plan[0].to_s, 100.0);
  EXPECT_EQ(plan[1].kind, StepKind::Track);
  EXPECT_DOUBLE_EQ(plan[1].from_s, 100.0);
  EXPECT_DOUBLE_EQ(plan[1].to_s, 500.0);
  // From the LOS at 270° back to 90°: 180° is 90 s + 5 s before the AOS at 700.
  EXPECT_EQ(plan[2].kind, StepKind::Preposition);
  EXPECT_DOUBLE_EQ(plan[2].from_s, 605.0);
  EXPECT_EQ(plan[3].kind, StepKind::Track);
}

TEST(PassSchedule, ARePlanMidPassKeepsThePassBeingTrackedWhenTheBetterOneMustWait) {
  // Priority 0 (finish) rose at 300 while priority 1 was tracked: a fresh plan from 400 would
  // take priority 0, a re-plan that knows what runs finishes priority 1 first.
  const std::vector<ScheduledPass> passes{pass(1, 0.0, 900.0), pass(0, 300.0, 1000.0)};
  const auto l = list({Preempt::Finish, Preempt::TakeOver});
  const auto fresh =
      of_kind(plan_schedule(l, passes, rules(), 400.0, 1100.0, {90.0, 0.0}), StepKind::Track);
  ASSERT_FALSE(fresh.empty());
  EXPECT_EQ(fresh[0].priority, 0U);
  const auto replan =
      of_kind(plan_schedule(l, passes, rules(), PlanStart{400.0, {90.0, 0.0}, 400.0, 1U}, 1100.0),
              StepKind::Track);
  ASSERT_EQ(replan.size(), 2U);
  EXPECT_EQ(replan[0].priority, 1U);
  EXPECT_DOUBLE_EQ(replan[0].from_s, 400.0);
  EXPECT_DOUBLE_EQ(replan[0].to_s, 900.0);
  EXPECT_EQ(replan[1].priority, 0U);
  EXPECT_DOUBLE_EQ(replan[1].from_s, 900.0);
}

TEST(PassSchedule, ARePlanDoesNotPostponeParkingByTheIdleTimeAlreadySpent) {
  // Idle since 0 with parking after 600 s: a re-plan at 500 still parks at 600.
  const auto plan = plan_schedule(list({Preempt::TakeOver}), {pass(0, 5000.0, 5400.0)}, rules(),
                                  PlanStart{500.0, {90.0, 0.0}, 0.0, {}}, 6000.0);
  const auto parks = of_kind(plan, StepKind::Park);
  ASSERT_FALSE(parks.empty());
  EXPECT_DOUBLE_EQ(parks[0].from_s, 600.0);
}

TEST(PassSchedule, AHigherPriorityAosTakesOverAndTheOtherResumesIfStillUp) {
  const auto plan = plan_schedule(list({Preempt::TakeOver, Preempt::TakeOver}),
                                  {pass(1, 0.0, 900.0), pass(0, 300.0, 600.0)}, rules(), 0.0,
                                  1000.0, {90.0, 0.0});
  const auto tracks = of_kind(plan, StepKind::Track);
  ASSERT_EQ(tracks.size(), 3U);
  EXPECT_EQ(tracks[0].priority, 1U);
  EXPECT_DOUBLE_EQ(tracks[0].to_s, 300.0);
  EXPECT_EQ(tracks[1].priority, 0U);
  EXPECT_DOUBLE_EQ(tracks[1].from_s, 300.0);
  EXPECT_DOUBLE_EQ(tracks[1].to_s, 600.0);
  EXPECT_EQ(tracks[2].priority, 1U);
  EXPECT_DOUBLE_EQ(tracks[2].from_s, 600.0);
  EXPECT_DOUBLE_EQ(tracks[2].to_s, 900.0);
}

TEST(PassSchedule, AFinishRuleLetsTheRunningPassEndFirst) {
  const auto plan = plan_schedule(list({Preempt::Finish, Preempt::TakeOver}),
                                  {pass(1, 0.0, 400.0), pass(0, 300.0, 600.0)}, rules(), 0.0,
                                  1000.0, {90.0, 0.0});
  const auto tracks = of_kind(plan, StepKind::Track);
  ASSERT_EQ(tracks.size(), 2U);
  EXPECT_EQ(tracks[0].priority, 1U);
  EXPECT_DOUBLE_EQ(tracks[0].to_s, 400.0);
  EXPECT_EQ(tracks[1].priority, 0U);
  EXPECT_DOUBLE_EQ(tracks[1].from_s, 400.0);  // joined midway, no pre-position possible
  EXPECT_DOUBLE_EQ(tracks[1].to_s, 600.0);
}

TEST(PassSchedule, PassesBelowTheEntrysMinimumElevationAreNotWorked) {
  auto priorities = list({Preempt::TakeOver});
  priorities[0].min_el_deg = 20.0;
  const auto plan =
      plan_schedule(priorities, {pass(0, 100.0, 300.0, 12.0), pass(0, 400.0, 700.0, 35.0)}, rules(),
                    0.0, 800.0, {90.0, 0.0});
  const auto tracks = of_kind(plan, StepKind::Track);
  ASSERT_EQ(tracks.size(), 1U);
  EXPECT_DOUBLE_EQ(tracks[0].from_s, 400.0);
}

TEST(PassSchedule, ALongIdleStretchParksThenPowersOffUntilJustBeforeThePreposition) {
  ScheduleRules r = rules();
  r.power_relay = true;
  const auto plan =
      plan_schedule(list({Preempt::TakeOver}), {pass(0, 0.0, 300.0), pass(0, 5000.0, 5300.0)}, r,
                    0.0, 5400.0, {90.0, 0.0});
  ASSERT_EQ(plan.size(), 5U);
  EXPECT_EQ(plan[1].kind, StepKind::Park);
  EXPECT_DOUBLE_EQ(plan[1].from_s, 900.0);             // LOS + 600 s idle
  EXPECT_DOUBLE_EQ(plan[1].to_s, 900.0 + 45.0 + 5.0);  // 270° → 180°
  EXPECT_EQ(plan[2].kind, StepKind::PowerOff);
  EXPECT_DOUBLE_EQ(plan[2].from_s, 950.0);
  // From park (180°) to the AOS (90°): 50 s, so the pre-position starts at 4950, power at 4945.
  EXPECT_DOUBLE_EQ(plan[2].to_s, 4945.0);
  EXPECT_EQ(plan[3].kind, StepKind::Preposition);
  EXPECT_DOUBLE_EQ(plan[3].from_s, 4950.0);
  EXPECT_EQ(plan[4].kind, StepKind::Track);
}

TEST(PassSchedule, WithoutARelayIdleParksButNeverPowersOff) {
  const auto plan = plan_schedule(list({Preempt::TakeOver}), {pass(0, 0.0, 300.0)}, rules(), 0.0,
                                  3000.0, {90.0, 0.0});
  EXPECT_EQ(of_kind(plan, StepKind::Park).size(), 1U);
  EXPECT_TRUE(of_kind(plan, StepKind::PowerOff).empty());
}

TEST(PassSchedule, ShortGapsNeitherParkNorPowerOff) {
  ScheduleRules r = rules();
  r.power_relay = true;
  const auto plan =
      plan_schedule(list({Preempt::TakeOver}), {pass(0, 0.0, 300.0), pass(0, 800.0, 1000.0)}, r,
                    0.0, 1000.0, {90.0, 0.0});
  EXPECT_TRUE(of_kind(plan, StepKind::Park).empty());
  EXPECT_TRUE(of_kind(plan, StepKind::PowerOff).empty());
}

TEST(PassSchedule, TheStepsAreInTimeOrderAndNeverOverlap) {
  // Random catalogues: whatever the passes, the plan is a time line, and no instant has a pass of
  // higher priority with the take-over rule up while another is tracked.
  std::mt19937 rng(20261129);
  std::uniform_real_distribution<double> start(0.0, 20000.0);
  std::uniform_real_distribution<double> length(200.0, 900.0);
  std::uniform_int_distribution<std::size_t> who(0, 3);
  const auto priorities =
      list({Preempt::TakeOver, Preempt::Finish, Preempt::TakeOver, Preempt::Finish});
  ScheduleRules r = rules();
  r.power_relay = true;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<ScheduledPass> passes;
    for (int i = 0; i < 20; ++i) {
      const double aos = start(rng);
      passes.push_back(pass(who(rng), aos, aos + length(rng)));
    }
    const auto plan = plan_schedule(priorities, passes, r, 0.0, 21000.0, {180.0, 0.0});
    for (std::size_t i = 1; i < plan.size(); ++i) {
      ASSERT_LE(plan[i - 1].to_s, plan[i].from_s + 1e-9) << "trial " << trial << " step " << i;
      ASSERT_LT(plan[i].from_s, plan[i].to_s + 1e-9);
    }
    for (const auto& t : of_kind(plan, StepKind::Track)) {
      for (const auto& p : passes) {
        const bool up = std::max(p.aos_s, t.from_s) < std::min(p.los_s, t.to_s);
        const bool missed =
            up && p.priority < *t.priority && priorities[p.priority].preempt == Preempt::TakeOver;
        ASSERT_FALSE(missed) << "trial " << trial << ": sat" << p.priority << " up from " << p.aos_s
                             << " while sat" << *t.priority << " was tracked";
      }
    }
  }
}

TEST(PassSchedule, NamesAreThePlansWords) {
  EXPECT_EQ(to_string(StepKind::PowerOff), "power_off");
  EXPECT_EQ(parse_preempt("finish"), Preempt::Finish);
  EXPECT_EQ(parse_preempt("take_over"), Preempt::TakeOver);
  EXPECT_FALSE(parse_preempt("sometimes").has_value());
}

}  // namespace
}  // namespace azt::schedule
