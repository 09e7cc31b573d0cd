#include "station/target_wait.hpp"

#include <cmath>
#include <memory>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/rise_search.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/util/format_number.hpp"
#include "common/sky_report.hpp"

namespace azt::app {
using json = nlohmann::json;

json TargetWait::waiting(const std::optional<astro::Target>& target, double el_deg,
                         double now_unix_s) {
  if (!target || el_deg >= p_.min_el_deg) {
    searched_for_.clear();  // up (or not tracked): the next setting is searched afresh
    return nullptr;
  }
  const bool passed = until_ && *until_ < now_unix_s - 60.0;
  if (!busy_ && (searched_for_ != target->name || passed)) search(*target, now_unix_s);
  json w{{"reason",
          target->name + " is below the horizon limit (" + format_number(p_.min_el_deg) + "°)"},
         {"until", nullptr},
         {"in_s", nullptr}};
  if (busy_) return w;
  if (!error_.empty()) {
    w["reason"] = w["reason"].get<std::string>() + "; its rise could not be found: " + error_;
  } else if (until_) {
    w["until"] = astro::format_iso8601_utc_unix(*until_);
    w["in_s"] = std::fmax(0.0, std::round(*until_ - now_unix_s));
  } else {
    w["reason"] = w["reason"].get<std::string>() + " and does not rise above it within two days";
  }
  return w;
}

void TargetWait::search(const astro::Target& target, double from_unix_s) {
  busy_ = true;
  searched_for_ = target.name;
  auto found = std::make_shared<Result<std::optional<double>>>(fail("not searched"));
  p_.offload(
      [found, target, settings = p_.sky.settings, min_el = p_.min_el_deg, from_unix_s] {
        const astro::ErfaEphemeris ephemeris;  // this thread's own
        const astro::ReachableAt above = [&](double t) -> Result<bool> {
          const auto sky =
              sky_snapshot(ephemeris, settings, astro::UtcInstant::from_unix_seconds(t));
          if (!sky) return sky.error();
          const auto r = sky->observe(target);
          if (!r) return r.error();
          return r->observation.el_deg >= min_el;
        };
        *found = astro::next_reachable(above, from_unix_s);
      },
      [this, found, name = target.name] {
        busy_ = false;
        if (name != searched_for_) return;  // another target meanwhile: searched again
        error_ = *found ? "" : found->error().message;
        until_ = *found ? found->value() : std::nullopt;
      });
}

}  // namespace azt::app
