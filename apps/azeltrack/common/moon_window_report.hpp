#pragma once
// One common Moon window as JSON (docs/eme.md), for `azeltrack moon-windows --json` and the
// console's planner alike: start, end, duration_s, best, dgrd_db, tsky_k, dpol_deg, sun_sep_deg,
// el_deg, dx_el_deg.

#include <nlohmann/json.hpp>

#include "azt/eme/moon_windows.hpp"

namespace azt::app {

nlohmann::json moon_window_json(const eme::MoonWindow& w);

}  // namespace azt::app
