#include "schedule/satellite_schedule.hpp"

#include <optional>

#include "common/usage_error.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

/// One satellite's passes as the planner takes them (Unix seconds), appended to `out`; the
/// search's error (a decayed orbit), if any.
std::optional<std::string> add_passes(const orbit::Satellite& sat, std::size_t priority,
                                      const ScheduleSite& st, double from_unix_s, double hours,
                                      std::vector<schedule::ScheduledPass>& out) {
  const auto from = astro::UtcInstant::from_unix_seconds(from_unix_s);
  auto found = orbit::find_satellite_passes(sat, from, hours, st.mask, st.dut1_s, st.site);
  if (!found) return sat.elements.label() + ": " + found.error().message;
  auto sky_at = [&sat, st](double unix_s) {
    const auto l =
        orbit::look(sat, astro::UtcInstant::from_unix_seconds(unix_s), st.dut1_s, st.site);
    return l ? control::AzEl{l->az_deg, l->el_deg} : control::AzEl{};
  };
  for (const orbit::Pass& p : found.value()) {
    out.push_back({priority,
                   from_unix_s + p.aos_s,
                   from_unix_s + p.los_s,
                   p.max_el_deg,
                   {p.aos_az_deg, 0.0},
                   {p.los_az_deg, 0.0},
                   sky_at});
  }
  return std::nullopt;
}

/// A NORAD number as a number; an alpha-5 one ("A0001") stays text.
json norad_json(const std::string& norad) {
  const bool digits = !norad.empty() && norad.size() < 10 &&
                      norad.find_first_not_of("0123456789") == std::string::npos;
  return digits ? json(std::stol(norad)) : json(norad);
}

}  // namespace

json plan_step_json(const SchedulePlan& plan, const schedule::PlanStep& s) {
  json j{{"kind", schedule::to_string(s.kind)},
         {"sat", nullptr},
         {"norad", nullptr},
         {"from", astro::format_iso8601_utc_unix(s.from_s)},
         {"to", astro::format_iso8601_utc_unix(s.to_s)}};
  if (s.priority) {
    j["sat"] = plan.priorities[*s.priority].sat;
    j["norad"] = norad_json(plan.priorities[*s.priority].norad);
  }
  return j;
}

namespace {

json pass_json(const SchedulePlan& plan, const PlannedPass& p) {
  const schedule::Priority& entry = plan.priorities[p.priority];
  return json{{"sat", entry.sat},
              {"norad", norad_json(entry.norad)},
              {"aos", astro::format_iso8601_utc_unix(p.aos_unix_s)},
              {"los", astro::format_iso8601_utc_unix(p.los_unix_s)},
              {"max_el_deg", p.max_el_deg},
              {"worked", p.max_el_deg >= entry.min_el_deg}};
}

}  // namespace

schedule::ScheduleRules schedule_rules_of(const DaemonConfig& config) {
  schedule::ScheduleRules rules;
  rules.idle_park_s = config.satellites.idle_park_min * 60.0;
  rules.park_sky = config.park[0].position;
  rules.az_rate_deg_s = config.station.az_control.max_rate_deg_s;
  rules.el_rate_deg_s = config.station.el_control.max_rate_deg_s;
  if (const auto& power = config.hardware.power) {
    rules.power_relay = true;
    // The relay's own lead, and a second for the tick that switches it.
    rules.power_on_lead_s = power->on_lead_s + 1.0;
  }
  return rules;
}

ScheduledSatellites scheduled_satellites(const SatelliteCatalogue& catalogue,
                                         const std::vector<ScheduleEntryConfig>& entries) {
  ScheduledSatellites out;
  for (const ScheduleEntryConfig& e : entries) {
    try {
      const orbit::Satellite& sat = catalogue.find(e.sat);  // names what is close when missing
      out.priorities.push_back(
          {sat.elements.label(), sat.elements.catalog, e.min_el_deg, e.preempt});
      out.sats.push_back(sat);
    } catch (const UsageError& missing) {
      out.missing.push_back(missing.what());
    }
  }
  return out;
}

SchedulePlan plan_schedule_over(const ScheduledSatellites& sats, const ScheduleSite& station,
                                const schedule::ScheduleRules& rules,
                                const schedule::PlanStart& start, double hours) {
  SchedulePlan plan{start.from_s, hours, sats.priorities, {}, {}, {}};
  std::vector<schedule::ScheduledPass> passes;
  for (std::size_t i = 0; i < sats.sats.size(); ++i) {
    if (auto error = add_passes(sats.sats[i], i, station, start.from_s, hours, passes)) {
      plan.errors.push_back(*error);
    }
  }
  for (const auto& p : passes) {
    plan.passes.push_back({p.priority, p.aos_s, p.los_s, p.max_el_deg});
  }
  plan.steps =
      schedule::plan_schedule(plan.priorities, passes, rules, start, start.from_s + hours * 3600.0);
  return plan;
}

const PlannedPass* pass_of(const SchedulePlan& plan, const schedule::PlanStep& step) {
  if (!step.priority) return nullptr;
  for (const PlannedPass& p : plan.passes) {
    // A track lies within its pass; a pre-position ends at the AOS (or the switch) it prepares.
    const double t = step.kind == schedule::StepKind::Preposition ? step.to_s : step.from_s;
    if (p.priority == *step.priority && p.aos_unix_s <= t && t < p.los_unix_s) return &p;
  }
  return nullptr;
}

json plan_json(const SchedulePlan& plan) {
  json steps = json::array();
  for (const auto& s : plan.steps) steps.push_back(plan_step_json(plan, s));
  json passes = json::array();
  for (const auto& p : plan.passes) passes.push_back(pass_json(plan, p));
  return json{{"from", astro::format_iso8601_utc_unix(plan.from_unix_s)},
              {"hours", plan.hours},
              {"plan", steps},
              {"passes", passes}};
}

json plan_satellite_schedule(const SatelliteCatalogue& catalogue,
                             const std::vector<ScheduleEntryConfig>& entries,
                             const ScheduleSite& station, const schedule::ScheduleRules& rules,
                             const astro::UtcInstant& from, double hours, control::AzEl start_sky) {
  const ScheduledSatellites sats = scheduled_satellites(catalogue, entries);
  if (!sats.missing.empty()) throw UsageError(sats.missing.front());
  const double from_unix_s = from.unix_seconds();
  const SchedulePlan plan = plan_schedule_over(
      sats, station, rules, schedule::PlanStart{from_unix_s, start_sky, from_unix_s, {}}, hours);
  if (!plan.errors.empty()) throw UsageError(plan.errors.front());
  return plan_json(plan);
}

}  // namespace azt::app
