#include "schedule/schedule_follower.hpp"

#include <memory>
#include <utility>

namespace azt::app {
namespace {

using json = nlohmann::json;

/// The plan is made again this often: the passes' times drift little, but a day-long plan must
/// keep reaching a day ahead, and the antenna's place is taken afresh.
constexpr double kReplanEveryS = 300.0;
constexpr double kPlanHours = 24.0;

CommandSource schedule_source() {
  return CommandSource{CommandSource::Kind::Schedule, ScheduleFollower::kSourceName};
}

bool follows_a_pass(const std::optional<schedule::PlanStep>& step) {
  return step &&
         (step->kind == schedule::StepKind::Track || step->kind == schedule::StepKind::Preposition);
}

}  // namespace

ScheduleFollower::ScheduleFollower(ScheduleFollowerParts parts,
                                   std::vector<ScheduleEntryConfig> entries, ScheduleSite site,
                                   schedule::ScheduleRules rules)
    : p_(std::move(parts)),
      entries_(std::move(entries)),
      site_(std::move(site)),
      rules_(rules),
      idle_since_unix_s_(p_.unix_s()) {
  rules_.power_relay = p_.power != nullptr;
}

void ScheduleFollower::set_entries(std::vector<ScheduleEntryConfig> entries) {
  entries_ = std::move(entries);
  replan_due_ = true;
  if (entries_.empty()) {
    plan_.reset();
    problems_.clear();
    power_on();  // nothing scheduled: nothing may keep the motors off
  }
}

void ScheduleFollower::set_observer(const astro::Observer& site) {
  site_.site = site;
  replan_due_ = true;
}

void ScheduleFollower::tick() {
  if (entries_.empty()) return;
  const double now = p_.unix_s();
  if ((replan_due_ || now >= next_replan_unix_s_) && !planning_) start_replan(now);
  if (!plan_ || held_by_) return;
  const schedule::PlanStep* step = step_at(now);
  const StepKey key = key_of(step);
  if (!(key == current_)) {
    leave(current_);
    current_ = key;
    current_step_ = step != nullptr ? std::optional(*step) : std::nullopt;
    enter(step);
  }
  keep_power(step);
}

void ScheduleFollower::start_replan(double unix_s) {
  planning_ = true;
  replan_due_ = false;
  next_replan_unix_s_ = unix_s + kReplanEveryS;
  // The element sets are copied here, on the loop; the pass searches (a few milliseconds per
  // satellite) run on the worker.
  auto sats = std::make_shared<ScheduledSatellites>(
      scheduled_satellites(p_.satellites.catalogue(), entries_));
  auto plan = std::make_shared<SchedulePlan>();
  p_.plan_off_loop(
      [sats, plan, site = site_, rules = rules_, start = plan_start(unix_s)] {
        *plan = plan_schedule_over(*sats, site, rules, start, kPlanHours);
      },
      [this, sats, plan] {
        planning_ = false;
        std::vector<std::string> problems = sats->missing;
        problems.insert(problems.end(), plan->errors.begin(), plan->errors.end());
        for (const auto& p : problems) {
          if (std::find(problems_.begin(), problems_.end(), p) == problems_.end()) {
            p_.log("schedule: " + p);
          }
        }
        problems_ = std::move(problems);
        if (!entries_.empty()) plan_ = std::move(*plan);
      });
}

schedule::PlanStart ScheduleFollower::plan_start(double unix_s) const {
  schedule::PlanStart start{unix_s, p_.antenna_sky(), idle_since_unix_s_, std::nullopt};
  if (follows_a_pass(current_step_)) start.idle_since_s = unix_s;
  if (current_step_ && current_step_->kind == schedule::StepKind::Track) {
    start.tracking = current_step_->priority;
  }
  return start;
}

const schedule::PlanStep* ScheduleFollower::step_at(double unix_s) const {
  for (const auto& s : plan_->steps) {
    if (s.from_s <= unix_s && unix_s < s.to_s) return &s;
  }
  return nullptr;
}

ScheduleFollower::StepKey ScheduleFollower::key_of(const schedule::PlanStep* step) const {
  if (step == nullptr) return {};
  const schedule::Priority* p = priority_of(*step);
  return {step->kind, p != nullptr ? p->norad : ""};
}

const schedule::Priority* ScheduleFollower::priority_of(const schedule::PlanStep& step) const {
  if (!step.priority || !plan_ || *step.priority >= plan_->priorities.size()) return nullptr;
  return &plan_->priorities[*step.priority];
}

void ScheduleFollower::leave(const StepKey& left) {
  if (!current_step_ || !left.kind) return;
  if (*left.kind == schedule::StepKind::Track) {
    p_.on_event(HookEvent::Los, priority_of(*current_step_),
                plan_ ? pass_of(*plan_, *current_step_) : nullptr);
  }
  if (follows_a_pass(current_step_)) idle_since_unix_s_ = p_.unix_s();
}

void ScheduleFollower::enter(const schedule::PlanStep* step) {
  if (step == nullptr) {
    // Between passes the antenna waits where it is; left following a satellite, the tracker
    // would swing it to that satellite's next AOS, hours away.
    if (p_.commands.tracking_satellite() && p_.commands.commander() == kSourceName) {
      p_.commands.stop(schedule_source());
    }
    return;
  }
  const PlannedPass* pass = pass_of(*plan_, *step);
  switch (step->kind) {
    case schedule::StepKind::Preposition:
      follow(*step);
      p_.on_event(HookEvent::PrePosition, priority_of(*step), pass);
      break;
    case schedule::StepKind::Track:
      follow(*step);
      p_.on_event(HookEvent::Aos, priority_of(*step), pass);
      break;
    case schedule::StepKind::Park:
      power_on();
      command(ParkTarget{1});
      p_.on_event(HookEvent::Park, nullptr, nullptr);
      break;
    case schedule::StepKind::PowerOff:
      break;  // keep_power() switches off once the antenna stands still
  }
}

void ScheduleFollower::follow(const schedule::PlanStep& step) {
  power_on();
  const schedule::Priority* p = priority_of(step);
  if (p == nullptr) return;
  if (p_.commands.tracking_satellite() && p_.commands.commander() == kSourceName &&
      p_.satellites.followed_norad() == p->norad) {
    return;
  }
  command(SatelliteTarget{p->norad});
}

void ScheduleFollower::command(const TargetRequest& request) {
  const CommandOutcome outcome = p_.commands.point(schedule_source(), request);
  // A refusal (a latched fault) is reported by the front door like any other; the schedule
  // goes on with the next step.
  if (outcome.refusal) p_.log("schedule: refused: " + outcome.refusal->reason);
}

void ScheduleFollower::power_on() {
  if (p_.power != nullptr) p_.power->switch_on(p_.monotonic_s());
}

void ScheduleFollower::keep_power(const schedule::PlanStep* step) {
  if (p_.power == nullptr) return;
  const bool off = step != nullptr && step->kind == schedule::StepKind::PowerOff;
  if (!off) {
    power_on();
  } else if (p_.power->on() && p_.antenna_still()) {
    p_.power->switch_off(p_.monotonic_s());
  }
}

void ScheduleFollower::on_command(const CommandSource& source) {
  if (source.kind == CommandSource::Kind::Schedule ||
      source.kind == CommandSource::Kind::Configuration || entries_.empty() || held_by_) {
    return;
  }
  held_by_ = source.name;
  p_.log("schedule held by " + source.name + " (resume it from the console)");
  power_on();
  current_ = StepKey{std::nullopt, "held"};
  current_step_.reset();
}

std::optional<std::string> ScheduleFollower::resume(const std::string& who) {
  if (entries_.empty()) return std::nullopt;
  if (held_by_) p_.log("schedule resumed by " + who);
  held_by_.reset();
  idle_since_unix_s_ = p_.unix_s();
  replan_due_ = true;  // from where the operator left the antenna
  return "schedule running";
}

json ScheduleFollower::step_json(const schedule::PlanStep* step) const {
  if (step == nullptr || !plan_) return nullptr;
  return plan_step_json(*plan_, *step);
}

json ScheduleFollower::state() const {
  if (entries_.empty()) return nullptr;
  const double now = p_.unix_s();
  const schedule::PlanStep* next = nullptr;
  if (plan_) {
    for (const auto& s : plan_->steps) {
      if (s.from_s > now) {
        next = &s;
        break;
      }
    }
  }
  return json{{"running", !held_by_.has_value()},
              {"held_by", held_by_ ? json(*held_by_) : json(nullptr)},
              {"step", plan_ && !held_by_ ? step_json(step_at(now)) : json(nullptr)},
              {"next", step_json(next)},
              {"power", p_.power == nullptr ? json(nullptr) : json(p_.power->on() ? "on" : "off")},
              {"problems", problems_}};
}

json ScheduleFollower::plan_view() const {
  json entries = json::array();
  for (const auto& e : entries_) {
    entries.push_back({{"sat", e.sat},
                       {"min_el_deg", e.min_el_deg},
                       {"preempt", schedule::to_string(e.preempt)}});
  }
  json view = plan_ ? plan_json(*plan_)
                    : json{{"from", nullptr},
                           {"hours", kPlanHours},
                           {"plan", json::array()},
                           {"passes", json::array()}};
  view["entries"] = entries;
  view["running"] = !held_by_.has_value();
  return view;
}

}  // namespace azt::app
