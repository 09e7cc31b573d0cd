#include "console/moon_planner.hpp"

#include <cmath>
#include <memory>

#include "azt/astro/bands.hpp"
#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/eme/moon_windows.hpp"
#include "azt/util/parse_number.hpp"
#include "common/moon_window_report.hpp"
#include "common/sky_setup.hpp"
#include "common/usage_error.hpp"
#include "console/query_string.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

constexpr double kMaxDays = 60.0;

double number(const std::string& query, const char* key, double fallback, double lo, double hi) {
  const auto text = query_value(query, key);
  if (!text) return fallback;
  const auto v = parse_finite_double(*text);
  if (!v || *v < lo || *v > hi) {
    throw ApiError(400, key,
                   std::string(key) + " must be a number from " + std::to_string(lo) + " to " +
                       std::to_string(hi));
  }
  return *v;
}

struct Plan {
  astro::Observer dx;
  std::string dx_grid;
  std::string band;
  eme::MoonWindowSettings settings;
};

Plan plan_from(const std::string& query, const MoonPlannerParts& parts, double now_unix_s) {
  const SkyConfig& sky = parts.sky;
  Plan p;
  p.dx_grid = query_value(query, "dx_grid").value_or(sky.settings.dx_grid);
  if (p.dx_grid.empty()) throw ApiError(400, "dx_grid", "a DX locator is needed (dx_grid=…)");
  try {
    p.dx = observer_from_grid(p.dx_grid, 0.0);
  } catch (const UsageError& e) {
    std::string why = e.what();  // "--grid: locator …": the planner's field is dx_grid
    if (why.rfind("--grid: ", 0) == 0) why.erase(0, 8);
    throw ApiError(400, "dx_grid", "dx_grid: " + why);
  }
  p.band = query_value(query, "band").value_or(sky.band_name);
  const astro::AmateurBand* band = astro::find_band(p.band);
  if (band == nullptr) throw ApiError(400, "band", "'" + p.band + "' is not a known band");
  eme::MoonWindowSettings& s = p.settings;
  s.freq_mhz = band->freq_mhz;
  s.days = number(query, "days", 30.0, 0.01, kMaxDays);
  s.min_el_deg = number(query, "min_el", 0.0, -5.0, 85.0);
  s.dx_min_el_deg = number(query, "dx_min_el", 0.0, -5.0, 85.0);
  s.from_unix_s = std::floor(now_unix_s);
  if (const auto from = query_value(query, "from")) {
    const auto t = astro::parse_iso8601_utc(*from);
    if (!t) throw ApiError(400, "from", "from: " + t.error().message);
    s.from_unix_s = t->unix_seconds();
  }
  if (parts.el_fixed)
    s = eme::in_fixed_beam(s, parts.el_fixed->el_deg, parts.el_fixed->beam_width_deg);
  return p;
}

}  // namespace

void MoonPlanner::answer(const std::string& query, ActDone done) {
  if (busy_) throw ApiError(503, "", "busy finding Moon windows: try again in a moment");
  const Plan plan = plan_from(query, p_, p_.unix_s());
  const astro::Observer own = p_.sky.settings.observer;
  auto found = std::make_shared<Result<std::vector<eme::MoonWindow>>>(fail("not searched"));
  busy_ = true;
  p_.offload(
      [found, own, plan] {
        const astro::ErfaEphemeris ephemeris;  // this thread's own: no state shared
        *found = eme::moon_windows(ephemeris, own, plan.dx, plan.settings, leap_table());
      },
      [this, found, plan, done = std::move(done)] {
        busy_ = false;
        if (!*found) {
          done(ActResult{{}, ApiError(400, "from", found->error().message)});
          return;
        }
        json windows = json::array();
        for (const auto& w : found->value()) windows.push_back(moon_window_json(w));
        json answer{{"grid", p_.sky.settings.grid},
                    {"dx_grid", plan.dx_grid},
                    {"band", plan.band},
                    {"from", astro::format_iso8601_utc_unix(plan.settings.from_unix_s)},
                    {"days", plan.settings.days},
                    {"min_el_deg", plan.settings.min_el_deg},
                    {"dx_min_el_deg", plan.settings.dx_min_el_deg},
                    {"ephemeris", "erfa"},
                    {"windows", windows}};
        const auto& s = plan.settings;
        if (s.max_el_deg) answer["el_band_deg"] = {s.min_el_deg, *s.max_el_deg};
        done(ActResult{std::move(answer), std::nullopt});
      });
}

}  // namespace azt::app
