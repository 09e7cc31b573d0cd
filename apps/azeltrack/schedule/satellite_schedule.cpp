#include "schedule/satellite_schedule.hpp"

#include "azt/orbit/satellite.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

/// One entry's passes, as the planner takes them (seconds after `from`).
std::vector<schedule::ScheduledPass> passes_of(const orbit::Satellite& sat, std::size_t priority,
                                               const ScheduleSite& st,
                                               const astro::UtcInstant& from, double hours) {
  auto found = orbit::find_satellite_passes(sat, from, hours, st.mask, st.dut1_s, st.site);
  if (!found) throw UsageError(sat.elements.label() + ": " + found.error().message);
  auto sky_at = [&sat, st, from](double t_s) {
    const auto l = orbit::look(sat, astro::utc_plus(from, t_s), st.dut1_s, st.site);
    return l ? control::AzEl{l->az_deg, l->el_deg} : control::AzEl{};
  };
  std::vector<schedule::ScheduledPass> out;
  for (const orbit::Pass& p : found.value()) {
    out.push_back({priority,
                   p.aos_s,
                   p.los_s,
                   p.max_el_deg,
                   {p.aos_az_deg, 0.0},
                   {p.los_az_deg, 0.0},
                   sky_at});
  }
  return out;
}

json step_json(const schedule::PlanStep& s, const std::vector<const orbit::Satellite*>& sats,
               const astro::UtcInstant& from) {
  const auto iso = [&from](double t) {
    return astro::format_iso8601_utc(astro::utc_plus(from, t));
  };
  json j{{"kind", schedule::to_string(s.kind)},
         {"sat", nullptr},
         {"norad", nullptr},
         {"from", iso(s.from_s)},
         {"to", iso(s.to_s)}};
  if (s.priority) {
    j["sat"] = sats[*s.priority]->elements.label();
    const std::string& norad = sats[*s.priority]->elements.catalog;
    // A number as NORAD numbers are; an alpha-5 number ("A0001") stays text.
    const bool digits =
        !norad.empty() && norad.find_first_not_of("0123456789") == std::string::npos;
    j["norad"] = digits ? json(std::stol(norad)) : json(norad);
  }
  return j;
}

}  // namespace

json plan_satellite_schedule(const SatelliteCatalogue& catalogue,
                             const std::vector<ScheduleEntryConfig>& entries,
                             const ScheduleSite& station, const schedule::ScheduleRules& rules,
                             const astro::UtcInstant& from, double hours, control::AzEl start_sky) {
  std::vector<schedule::Priority> priorities;
  std::vector<const orbit::Satellite*> sats;
  std::vector<schedule::ScheduledPass> passes;
  for (const ScheduleEntryConfig& e : entries) {
    const orbit::Satellite& sat = catalogue.find(e.sat);  // UsageError naming what is close
    priorities.push_back({e.sat, sat.elements.catalog, e.min_el_deg, e.preempt});
    sats.push_back(&sat);
    auto found = passes_of(sat, sats.size() - 1, station, from, hours);
    passes.insert(passes.end(), found.begin(), found.end());
  }
  json plan = json::array();
  for (const auto& s :
       schedule::plan_schedule(priorities, passes, rules, 0.0, hours * 3600.0, start_sky)) {
    plan.push_back(step_json(s, sats, from));
  }
  return json{{"from", astro::format_iso8601_utc(from)}, {"hours", hours}, {"plan", plan}};
}

}  // namespace azt::app
