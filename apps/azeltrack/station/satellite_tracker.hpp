#pragma once
// A satellite as the daemon's target (docs/satellites.md): the next pass is planned as a whole at
// selection (or after the previous LOS), the antenna is pre-positioned to where the plan starts,
// and through the pass the planned mount position is the demand (never re-planned to the nearest
// side mid-pass). The catalogue comes whole from the element feed (elements/element_feed.hpp:
// the sources, the file and uploads, merged), and is swapped in one move. Elements older than
// `refuse_days` are not tracked (azt/orbit/element_age.hpp), with the reason as the problem.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/control/modes.hpp"
#include "azt/orbit/element_age.hpp"
#include "azt/orbit/passes.hpp"
#include "azt/track/pass_plan.hpp"
#include "satellites/satellite_catalogue.hpp"

namespace azt::app {

struct SatelliteSettings {
  orbit::HorizonMask mask;
  orbit::ElementAgeLimits age;  ///< [satellites] stale_days, refuse_days
  /// [satellites] min_el_deg: the console's pass lists leave out lower passes (a pass is still
  /// tracked whatever its height when the satellite is chosen).
  double list_min_el_deg = 10.0;
  double dut1_s = 0.0;
  astro::Observer site;
  track::MountGeometry mount;
};

class SatelliteTracker {
 public:
  SatelliteTracker(SatelliteSettings settings, std::function<void(const std::string&)> log);

  /// A new catalogue, whole (the feed merged it off the loop). The followed satellite keeps
  /// a pass under way as planned; before AOS its pass is planned again from the new elements.
  void adopt(SatelliteCatalogue catalogue, double unix_s);
  [[nodiscard]] const SatelliteCatalogue& catalogue() const { return catalogue_; }

  /// Starts following a satellite (name or NORAD number); the error names it.
  Result<std::string> follow(const std::string& name_or_norad, double unix_s, double mount_az_deg);
  void stop() { following_.reset(); }
  /// The station's place changed (the console, or the GPS survey): every pass list is found
  /// again, and the followed satellite's pass is planned again from the new place at the next
  /// demand, unless a pass is under way: that one is finished as planned (a re-plan mid-pass
  /// could choose the other wrap side and swing the antenna), and the next uses the new place.
  void set_site(const astro::Observer& site);
  [[nodiscard]] bool following() const { return following_.has_value(); }
  /// The NORAD number of the followed satellite ("" when none).
  [[nodiscard]] std::string followed_norad() const { return following_.value_or(""); }

  /// The demand at `unix_s`: the planned mount position (pre-positioning before AOS), or
  /// nothing to do (hold) when no pass is found. `rate` gets the plan's rate for feed-forward.
  control::Demand demand(double unix_s, double mount_az_deg, control::AzEl& rate);

  /// {"sat","norad","phase","aos","tca","los","max_el_deg","flip","element_age_days","stale",
  /// "refused" (null, or why it is not tracked),"az_deg","el_deg"} for the followed satellite;
  /// null when none.
  [[nodiscard]] nlohmann::json status(double unix_s) const;
  /// Every satellite with its position now and its passes in the next 24 h (as last found by
  /// refresh_passes()).
  [[nodiscard]] nlohmann::json list(double unix_s) const;
  /// Finds the next day's passes of one satellite, the next in turn, each at most once a minute:
  /// called every control tick, so a large catalogue never stalls the loop (a satellite's 24-hour
  /// search is about a millisecond; all of a hundred at once would be a tenth of a second).
  void refresh_passes(double unix_s);
  /// The followed satellite's planned pass as sky points (for the sky plot), every 10 s.
  [[nodiscard]] nlohmann::json pass_track() const;

 private:
  struct Planned {
    orbit::Pass pass;  ///< times are Unix seconds
    track::PassPlan plan;
    std::vector<track::SkyPoint> sky;
  };
  void plan_next(double unix_s, double mount_az_deg);
  [[nodiscard]] const orbit::Satellite* current() const;

  SatelliteSettings s_;
  std::function<void(const std::string&)> log_;
  SatelliteCatalogue catalogue_;
  std::optional<std::string> following_;  ///< NORAD number of the followed satellite
  std::optional<Planned> planned_;
  double next_plan_s_ = -1e9;  ///< when to search again after finding no pass
  std::string problem_;        ///< why there is no plan (decayed, no pass in 48 h)
  bool site_changed_ = false;  ///< the plan is from the old place: re-plan outside a pass
  struct Upcoming {
    double at_s = -1e9;
    nlohmann::json passes;  ///< null until first found
  };
  std::vector<Upcoming> upcoming_;  ///< per catalogue entry, same order
  std::size_t next_refresh_ = 0;
};

}  // namespace azt::app
