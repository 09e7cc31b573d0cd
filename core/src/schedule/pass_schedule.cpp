#include "azt/schedule/pass_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace azt::schedule {
namespace {

/// A stretch of one pass tracked: [from_s, to_s).
struct Segment {
  std::size_t pass = 0;
  double from_s = 0.0;
  double to_s = 0.0;
};

bool up_at(const ScheduledPass& p, double t_s) { return p.aos_s <= t_s && t_s < p.los_s; }

/// The best pass up at `t_s` among those `eligible` allows: the highest priority, then the
/// earlier AOS.
std::optional<std::size_t> best_up(const std::vector<ScheduledPass>& passes, double t_s,
                                   const std::function<bool(const ScheduledPass&)>& eligible) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    if (!up_at(passes[i], t_s) || !eligible(passes[i])) continue;
    const bool better =
        !best || passes[i].priority < passes[*best].priority ||
        (passes[i].priority == passes[*best].priority && passes[i].aos_s < passes[*best].aos_s);
    if (better) best = i;
  }
  return best;
}

/// Which pass is tracked at `t_s`, given the one tracked just before: it goes on until its LOS
/// unless a pass of higher priority whose rule is TakeOver is up.
std::optional<std::size_t> choose(const std::vector<Priority>& priorities,
                                  const std::vector<ScheduledPass>& passes,
                                  std::optional<std::size_t> running, double t_s) {
  if (running && !up_at(passes[*running], t_s)) running.reset();
  if (!running) return best_up(passes, t_s, [](const ScheduledPass&) { return true; });
  const std::size_t rank = passes[*running].priority;
  const auto taker = best_up(passes, t_s, [&](const ScheduledPass& p) {
    return p.priority < rank && priorities[p.priority].preempt == Preempt::TakeOver;
  });
  return taker ? taker : running;
}

/// The instants at which the choice can change: every AOS and LOS inside the window.
std::vector<double> events(const std::vector<ScheduledPass>& passes, double from_s, double to_s) {
  std::set<double> t{from_s};
  for (const auto& p : passes) {
    for (double e : {p.aos_s, p.los_s}) {
      if (e > from_s && e < to_s) t.insert(e);
    }
  }
  return {t.begin(), t.end()};
}

/// The pass of `priority` up at `t_s`: the one being tracked when a re-plan starts.
std::optional<std::size_t> pass_up(const std::vector<ScheduledPass>& passes,
                                   std::optional<std::size_t> priority, double t_s) {
  if (!priority) return std::nullopt;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    if (passes[i].priority == *priority && up_at(passes[i], t_s)) return i;
  }
  return std::nullopt;
}

std::vector<Segment> segments(const std::vector<Priority>& priorities,
                              const std::vector<ScheduledPass>& passes, const PlanStart& start,
                              double to_s) {
  const double from_s = start.from_s;
  std::vector<Segment> out;
  std::optional<std::size_t> running = pass_up(passes, start.tracking, from_s);
  const auto instants = events(passes, from_s, to_s);
  for (std::size_t k = 0; k < instants.size(); ++k) {
    running = choose(priorities, passes, running, instants[k]);
    if (!running) continue;
    const double end = k + 1 < instants.size() ? instants[k + 1] : to_s;
    if (!out.empty() && out.back().pass == *running && out.back().to_s == instants[k]) {
      out.back().to_s = end;
    } else {
      out.push_back({*running, instants[k], end});
    }
  }
  return out;
}

control::AzEl sky_of(const ScheduledPass& p, double t_s) {
  if (p.sky_at) return p.sky_at(t_s);
  return t_s >= p.los_s ? p.los_sky : p.aos_sky;
}

/// The plan's walk: where the antenna is, until when it is busy, and the steps so far.
class Planner {
 public:
  Planner(const ScheduleRules& rules, const PlanStart& start)
      : rules_(rules), free_from_s_(std::min(start.idle_since_s, start.from_s)), at_(start.sky) {}

  void track(const ScheduledPass& pass, const Segment& s) {
    const control::AzEl first = sky_of(pass, s.from_s);
    const double lead_from_s = std::max(rest_until(s.from_s, first), free_from_s_);
    if (lead_from_s < s.from_s) {
      steps_.push_back({StepKind::Preposition, pass.priority, lead_from_s, s.from_s});
    }
    steps_.push_back({StepKind::Track, pass.priority, s.from_s, s.to_s});
    at_ = sky_of(pass, s.to_s);
    free_from_s_ = s.to_s;
  }

  std::vector<PlanStep> finish(double to_s) {
    if (to_s - free_from_s_ >= rules_.idle_park_s) {
      park();
      power_off_until(to_s);
    }
    return std::move(steps_);
  }

 private:
  /// The idle stretch before the antenna must be at `next` by `busy_s`: parked (then powered
  /// off) when it is long enough. Returns when the move to `next` starts.
  double rest_until(double busy_s, const control::AzEl& next) {
    const double lead_from_s = busy_s - slew_time_s(at_, next, rules_);
    if (lead_from_s - free_from_s_ < rules_.idle_park_s) return lead_from_s;
    park();
    const double from_park_s = std::max(free_from_s_, busy_s - slew_time_s(at_, next, rules_));
    power_off_until(from_park_s - rules_.power_on_lead_s);
    return from_park_s;
  }

  void park() {
    const double park_from_s = free_from_s_ + rules_.idle_park_s;
    const double parked_s = park_from_s + slew_time_s(at_, rules_.park_sky, rules_);
    steps_.push_back({StepKind::Park, std::nullopt, park_from_s, parked_s});
    at_ = rules_.park_sky;
    free_from_s_ = parked_s;
  }

  void power_off_until(double until_s) {
    if (rules_.power_relay && until_s > free_from_s_) {
      steps_.push_back({StepKind::PowerOff, std::nullopt, free_from_s_, until_s});
    }
  }

  const ScheduleRules& rules_;
  double free_from_s_;
  control::AzEl at_;
  std::vector<PlanStep> steps_;
};

}  // namespace

std::optional<Preempt> parse_preempt(std::string_view text) {
  if (text == "take_over") return Preempt::TakeOver;
  if (text == "finish") return Preempt::Finish;
  return std::nullopt;
}

std::string_view to_string(Preempt preempt) {
  switch (preempt) {
    case Preempt::TakeOver:
      return "take_over";
    case Preempt::Finish:
      return "finish";
  }
  return "?";
}

std::string_view to_string(StepKind kind) {
  switch (kind) {
    case StepKind::Track:
      return "track";
    case StepKind::Preposition:
      return "preposition";
    case StepKind::Park:
      return "park";
    case StepKind::PowerOff:
      return "power_off";
  }
  return "?";
}

double slew_time_s(const control::AzEl& from, const control::AzEl& to, const ScheduleRules& rules) {
  // The short way round in azimuth: an estimate for the lead time; the mount's own planner picks
  // the side, and the settle time covers a turn of cable wrap's worth of difference poorly, which
  // is why a pass's pre-position starts at the latest when the previous one ends.
  const double az = std::fabs(std::remainder(to.az_deg - from.az_deg, 360.0));
  const double el = std::fabs(to.el_deg - from.el_deg);
  return std::max(az / rules.az_rate_deg_s, el / rules.el_rate_deg_s) + rules.settle_s;
}

std::vector<PlanStep> plan_schedule(const std::vector<Priority>& priorities,
                                    const std::vector<ScheduledPass>& passes,
                                    const ScheduleRules& rules, double from_s, double to_s,
                                    control::AzEl start_sky) {
  return plan_schedule(priorities, passes, rules, PlanStart{from_s, start_sky, from_s, {}}, to_s);
}

std::vector<PlanStep> plan_schedule(const std::vector<Priority>& priorities,
                                    const std::vector<ScheduledPass>& passes,
                                    const ScheduleRules& rules, const PlanStart& start,
                                    double to_s) {
  const double from_s = start.from_s;
  std::vector<ScheduledPass> worked;
  for (const auto& p : passes) {
    const bool known = p.priority < priorities.size();
    if (known && p.max_el_deg >= priorities[p.priority].min_el_deg && p.los_s > from_s &&
        p.aos_s < to_s) {
      worked.push_back(p);
    }
  }
  Planner planner(rules, start);
  for (const Segment& s : segments(priorities, worked, start, to_s)) {
    planner.track(worked[s.pass], s);
  }
  return planner.finish(to_s);
}

}  // namespace azt::schedule
