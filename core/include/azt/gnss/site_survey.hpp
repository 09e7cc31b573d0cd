#pragma once
// The station's position from its GPS (docs/gps.md): once a 3D fix with enough satellites has
// held for a settable time, the average of the fixes seen is the surveyed site. A fix that drops
// to 2D, loses satellites, falls silent for more than 5 s or lands more than jump_m from the
// run's mean restarts the survey: the average is only ever of one unbroken run of good fixes.
// decide_site() says what to do with a survey: a site more than jump_m from the one in use is not
// adopted while the station tracks.

#include <cstddef>
#include <optional>
#include <string_view>

#include "azt/gnss/gps_fix.hpp"

namespace azt::gnss {

struct SiteSurveySettings {
  double hold_s = 60.0;   ///< a 3D fix must hold this long before its average is used
  int min_sats = 4;       ///< satellites used by a fix that counts
  double jump_m = 100.0;  ///< a survey this far from the site in use is a jump
};

class SiteSurvey {
 public:
  explicit SiteSurvey(SiteSurveySettings settings) : settings_(settings) {}

  /// Each TPV at `now_s` (the caller's monotonic clock, in seconds), with the SKY's satellites
  /// used at that moment. A 3D fix (with a place and altitude on the Earth: fix_range.hpp) from
  /// at least min_sats satellites joins the running average; anything else (2D, no fix, too few
  /// satellites) restarts the survey, as does more than 5 s between good fixes: the fix must hold.
  void on_fix(double now_s, const GpsFix& fix, int sats_used);
  /// The mean of the fixes since the survey (re)started, once the 3D fix has held for hold_s
  /// (from the run's first fix to its latest); nullopt before. Longitudes are averaged across
  /// ±180° (unwrapped around the run's first fix; the mean is wrapped back to (-180, 180]).
  [[nodiscard]] std::optional<Site> surveyed() const;
  /// How many fixes the current average holds.
  [[nodiscard]] std::size_t fixes() const { return n_; }

 private:
  void restart();
  /// A fix farther than jump_m from the run's mean: the antenna (or the receiver) moved, and a
  /// new survey starts there rather than letting the average creep towards it.
  [[nodiscard]] bool moved_away(const GpsFix& fix) const;

  SiteSurveySettings settings_;
  std::optional<double> first_s_;
  std::optional<double> last_s_;
  double lon_ref_deg_ = 0.0;  ///< the run's first longitude: the others are unwrapped around it
  double sum_lat_deg_ = 0.0;
  double sum_dlon_deg_ = 0.0;
  double sum_alt_m_ = 0.0;
  std::size_t n_ = 0;
};

enum class SiteDecision { Keep, Adopt, Jump };

/// "keep", "adopt", "jump".
std::string_view to_string(SiteDecision d);

/// What to do with a surveyed site, given the GPS site in use (nullopt: none yet) and whether
/// the station is tracking: none in use → Adopt; within 1 m → Keep (no real change); farther
/// than jump_m → Jump while tracking (shown and logged, not adopted), Adopt otherwise; else Adopt.
SiteDecision decide_site(const std::optional<Site>& in_use, const Site& surveyed, bool tracking,
                         double jump_m);

}  // namespace azt::gnss
