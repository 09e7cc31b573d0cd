#pragma once
// Satellites for the command line and the daemon (issue 7): a catalogue of element sets (TLE or
// OMM) with their SGP4 propagators, where each one is from a station, and its passes.
//
// Times: SGP4 is fed the UTC Julian date; the Earth's rotation uses UT1 = UTC + DUT1 (the
// convention of issue 7 §1). A satellite whose elements do not initialise, or whose orbit has
// decayed, is an error for that satellite alone.

#include <optional>
#include <string>
#include <vector>

#include "azt/astro/observer.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/orbit/elements.hpp"
#include "azt/orbit/look_angles.hpp"
#include "azt/orbit/passes.hpp"
#include "azt/orbit/sgp4.hpp"
#include "azt/track/pass_plan.hpp"
#include "azt/util/result.hpp"

namespace azt::app {

struct Satellite {
  orbit::Elements elements;
  orbit::Sgp4 sgp4;
};

class SatelliteCatalogue {
 public:
  /// Parses a catalogue file's text (TLE, or OMM in XML / JSON / KVN / CSV). Entries that do not
  /// parse or initialise are kept as named errors; the others are usable.
  static SatelliteCatalogue parse(std::string_view text, const std::string& source);
  /// Reads and parses `path`; throws UsageError when it cannot be read.
  static SatelliteCatalogue load(const std::string& path);

  /// By NORAD number, or by name (case-insensitive; an exact match before a unique prefix).
  /// Throws UsageError naming what was asked and, for a name, what is close.
  [[nodiscard]] const Satellite& find(const std::string& name_or_norad) const;
  [[nodiscard]] const std::vector<Satellite>& satellites() const { return satellites_; }
  [[nodiscard]] const std::vector<std::string>& errors() const { return errors_; }
  [[nodiscard]] const std::string& source() const { return source_; }

 private:
  std::vector<Satellite> satellites_;
  std::vector<std::string> errors_;
  std::string source_;
};

/// The element set's age at `utc`, days (negative: the epoch is in the future).
double element_age_days(const orbit::Elements& e, const astro::UtcInstant& utc);
/// Element sets older than this are flagged stale (LEO predictions drift by kilometres a day).
inline constexpr double kStaleElementDays = 7.0;

/// Where `sat` is seen from `site` at `utc`.
Result<orbit::LookAngles> look(const Satellite& sat, const astro::UtcInstant& utc, double dut1_s,
                               const astro::Observer& site);

/// The UTC instant `seconds` after `from` (two-part Julian date arithmetic, no rounding to ms).
astro::UtcInstant utc_plus(const astro::UtcInstant& from, double seconds);

/// Passes in [from, from + hours] above `mask`. Times in the result are seconds after `from`.
Result<std::vector<orbit::Pass>> find_satellite_passes(const Satellite& sat,
                                                       const astro::UtcInstant& from, double hours,
                                                       const orbit::HorizonMask& mask,
                                                       double dut1_s, const astro::Observer& site);

/// The pass sampled every second from its AOS to its LOS (pass times are seconds after `from`);
/// each point's time is its pass time plus `time_offset_s`. The error names the satellite.
Result<std::vector<track::SkyPoint>> sample_pass(const Satellite& sat,
                                                 const astro::UtcInstant& from,
                                                 const orbit::Pass& pass, double dut1_s,
                                                 const astro::Observer& site,
                                                 double time_offset_s = 0.0);

}  // namespace azt::app
