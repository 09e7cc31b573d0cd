#pragma once
// The console's Moon planner (docs/eme.md): GET /api/moon-windows, the common Moon windows with
// a DX station. Finding thirty days of them takes a fraction of a second, so it runs on the
// worker thread, one at a time (a second request meanwhile is told to wait), with an ephemeris
// of its own: ERFA's, whose functions share no state with the loop's (libswe's global state
// could not be used from two threads).

#include <functional>
#include <string>

#include "common/off_loop.hpp"
#include "config/mount_config.hpp"
#include "config/sky_config.hpp"
#include "console/console_model.hpp"

namespace azt::app {

struct MoonPlannerParts {
  const SkyConfig& sky;  ///< the running station: place, DX, band
  /// A fixed-elevation array ([mount.el] fixed_deg): the Moon counts only within its beam.
  std::optional<FixedElevation> el_fixed;
  Offload offload;
  std::function<double()> unix_s;
};

class MoonPlanner {
 public:
  explicit MoonPlanner(MoonPlannerParts parts) : p_(std::move(parts)) {}

  /// `query`: dx_grid (default: the station's [sky] dx_grid), days (0–60, default 30), from
  /// (ISO 8601 UTC, default now), min_el and dx_min_el (−5…85°, default 0), band (default the
  /// station's). A fixed-elevation station's windows are those with the Moon in its vertical beam
  /// (the answer's el_band_deg). A bad value is a 400 naming it; 503 while another search runs.
  void answer(const std::string& query, ActDone done);

 private:
  MoonPlannerParts p_;
  bool busy_ = false;
};

}  // namespace azt::app
