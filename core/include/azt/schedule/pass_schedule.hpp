#pragma once
// The satellite schedule (docs/satellites.md "The schedule"): from a priority list and the passes
// of its satellites, what the station does and when — track, pre-position before an AOS, park
// after a long idle stretch, and switch the motors' power off until the next pre-position. Pure:
// the passes come from the orbit's pass search, times are seconds on the caller's uniform scale
// (Unix UTC in the daemon and the CLI), so `azeltrack schedule` and the daemon plan alike.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/control/modes.hpp"

namespace azt::schedule {

/// What a satellite's AOS does to a running pass of lower priority: takes over at once, or waits
/// for it to finish (and starts then if still up).
enum class Preempt { TakeOver, Finish };
std::optional<Preempt> parse_preempt(std::string_view text);  ///< "take_over" | "finish"
std::string_view to_string(Preempt preempt);

/// One entry of the priority list, highest priority first.
struct Priority {
  std::string sat;          ///< the satellite's name as the operator wrote it
  std::string norad;        ///< the NORAD catalogue number as the elements give it ("25544")
  double min_el_deg = 0.0;  ///< a pass whose highest point is lower is not worked
  Preempt preempt = Preempt::TakeOver;
};

/// A pass of one entry's satellite (orbit::Pass, with the entry it belongs to).
struct ScheduledPass {
  std::size_t priority = 0;  ///< index into the priority list
  double aos_s = 0.0;
  double los_s = 0.0;
  double max_el_deg = 0.0;
  control::AzEl aos_sky;
  control::AzEl los_sky;
  /// Where the satellite is at a time within the pass (for a pass taken over or resumed midway);
  /// empty: the AOS and LOS positions stand in.
  std::function<control::AzEl(double t_s)> sky_at;
};

struct ScheduleRules {
  double idle_park_s = 600.0;    ///< idle this long: park (then power off, with a relay)
  bool power_relay = false;      ///< [hardware.power]: the motors' power can be switched
  double power_on_lead_s = 5.0;  ///< the relay is on this long before a pre-position starts
  control::AzEl park_sky;        ///< where parking goes (park slot 1)
  double az_rate_deg_s = 1.5;    ///< the mount's slew rates, for the pre-position's lead time
  double el_rate_deg_s = 1.5;
  double settle_s = 5.0;  ///< added to every slew: start, stop, the last counts
};

enum class StepKind { Track, Preposition, Park, PowerOff };
std::string_view to_string(StepKind kind);

/// One step of the plan: [from_s, to_s). `priority` names the satellite for Track and
/// Preposition (the one it prepares for), nothing for Park and PowerOff.
struct PlanStep {
  StepKind kind = StepKind::Track;
  std::optional<std::size_t> priority;
  double from_s = 0.0;
  double to_s = 0.0;
};

/// Where the plan starts from. The daemon plans again every few minutes and whenever the
/// catalogue or the list changes, so the plan must continue what runs: the pass being tracked
/// (a pass whose rule is Finish does not take it over at a re-plan), and the idle time already
/// spent (re-planning does not postpone parking).
struct PlanStart {
  double from_s = 0.0;
  control::AzEl sky;  ///< where the antenna is at from_s
  /// Since when the antenna has had nothing to do (at most from_s); from_s when it is busy.
  double idle_since_s = 0.0;
  /// The priority whose pass is being tracked at from_s, if one is.
  std::optional<std::size_t> tracking;
};

/// The time the mount takes from `from` to `to` (the slower axis, plus the settle time).
double slew_time_s(const control::AzEl& from, const control::AzEl& to, const ScheduleRules& rules);

/// The plan over [from_s, to_s) in time order, the antenna at `start_sky` at from_s with its
/// motors powered. Passes below their entry's minimum elevation are left out; at every instant
/// the tracked pass is the best one up, except while a pass of lower priority finishes because
/// the better one's rule is Finish.
std::vector<PlanStep> plan_schedule(const std::vector<Priority>& priorities,
                                    const std::vector<ScheduledPass>& passes,
                                    const ScheduleRules& rules, const PlanStart& start,
                                    double to_s);
/// A fresh plan: the antenna idle and at `start_sky` from `from_s`.
std::vector<PlanStep> plan_schedule(const std::vector<Priority>& priorities,
                                    const std::vector<ScheduledPass>& passes,
                                    const ScheduleRules& rules, double from_s, double to_s,
                                    control::AzEl start_sky);

}  // namespace azt::schedule
