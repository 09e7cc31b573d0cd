#pragma once
// Satellite passes (docs/satellites.md): AOS, TCA (highest elevation) and LOS above a horizon mask,
// found by root-finding on the elevation, not by stepping and hoping.
//
// The search steps through the window and brackets every maximum of the elevation, then refines
// it (golden section) and, where it clears the mask, bisects the rise and the set to a
// millisecond. Steps are long while the satellite is far below the horizon: a satellite below
// the horizon is at least the horizon distance d away, so its elevation cannot change faster
// than v_max / d, which bounds how soon it can rise; near the horizon the step is the base step,
// small against the shortest pass of the orbit.

#include <functional>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/orbit/look_angles.hpp"
#include "azt/util/result.hpp"

namespace azt::orbit {

/// The lowest usable elevation per azimuth sector: {az_from_deg, min_el_deg} pairs; a sector runs
/// to the next one's start (the last wraps to the first). A single pair is a flat horizon.
class HorizonMask {
 public:
  HorizonMask() = default;
  /// Validates: 1–72 sectors, starts 0 ≤ az < 360 strictly increasing, elevations −10..90.
  static Result<HorizonMask> make(std::vector<std::pair<double, double>> sectors);
  /// From text as operators type it: one elevation ("5", a flat horizon) or "AZ:MIN_EL" sectors
  /// separated by commas ("0:5,90:12,200:3"); the error quotes what could not be read.
  static Result<HorizonMask> parse(std::string_view text);
  static HorizonMask flat(double min_el_deg);
  [[nodiscard]] double min_el_at(double az_deg) const;
  [[nodiscard]] double lowest() const;
  [[nodiscard]] const std::vector<std::pair<double, double>>& sectors() const { return sectors_; }

 private:
  std::vector<std::pair<double, double>> sectors_{{0.0, 0.0}};
};

struct Pass {
  double aos_s = 0.0;  ///< rise above the mask (the window's start if it began in the pass)
  double tca_s = 0.0;  ///< highest elevation
  double los_s = 0.0;  ///< set below the mask (the window's end if it ends in the pass)
  double max_el_deg = 0.0;
  double aos_az_deg = 0.0;
  double tca_az_deg = 0.0;
  double los_az_deg = 0.0;
  bool starts_before_window = false;
  bool ends_after_window = false;
};

/// The look angles at a time (seconds on any uniform scale the caller chooses, e.g. Unix UTC);
/// an error (a decayed orbit) ends the search with that error.
using LookFunction = std::function<Result<LookAngles>(double t_s)>;

struct PassSearch {
  double from_s = 0.0;
  double to_s = 0.0;
  HorizonMask mask;
  /// Near the horizon: at most this between samples. Keep it below half the shortest pass to be
  /// found; orbit_pass_search() uses 1/200 of the period.
  double base_step_s = 20.0;
  /// The horizon distance of the orbit's lowest point (km) and the fastest the satellite can move
  /// relative to the site (km/s): together they bound how fast the elevation can rise.
  double horizon_km = 0.0;
  double max_speed_km_s = 0.0;
  double time_tolerance_s = 1e-3;
};

/// Every pass that clears the mask in [from_s, to_s], in time order.
Result<std::vector<Pass>> find_passes(const LookFunction& look, const PassSearch& search);

/// The step and bounds for an orbit of mean motion `rev_day`, eccentricity `e` (SGP4's mean
/// elements): base step 1/200 of the period (5–600 s), horizon distance at perigee.
PassSearch orbit_pass_search(double rev_day, double eccentricity, double from_s, double to_s,
                             const HorizonMask& mask);

}  // namespace azt::orbit
