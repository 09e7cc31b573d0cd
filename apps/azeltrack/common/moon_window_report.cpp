#include "common/moon_window_report.hpp"

#include "azt/astro/time_scales.hpp"

namespace azt::app {
nlohmann::json moon_window_json(const eme::MoonWindow& w) {
  return {{"start", astro::format_iso8601_utc_unix(w.start_unix_s)},
          {"end", astro::format_iso8601_utc_unix(w.end_unix_s)},
          {"duration_s", w.end_unix_s - w.start_unix_s},
          {"best", astro::format_iso8601_utc_unix(w.best_unix_s)},
          {"dgrd_db", w.dgrd_db},
          {"tsky_k", w.tsky_k},
          {"dpol_deg", w.dpol_deg},
          {"sun_sep_deg", w.sun_sep_deg},
          {"el_deg", w.el_deg},
          {"dx_el_deg", w.dx_el_deg}};
}

}  // namespace azt::app
