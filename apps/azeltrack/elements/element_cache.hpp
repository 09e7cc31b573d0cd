#pragma once
// The element-set cache under the state directory (docs/satellites.md, "Elements from the
// network"): what each source last gave that was accepted, with when, so that a restart without
// the network has the same catalogue and each source's history (the epochs a new download must
// not go back from, the count it must not collapse from) survives.
//
// The file is JSON: {"format": "azeltrack element cache 1", "sources": [{"url", "last_ok",
// "sets": [[name, norad, designator, classification, epoch_jd, epoch_jd_frac, ndot/2, nddot/6,
// bstar, inclination_deg, raan_deg, eccentricity, arg_perigee_deg, mean_anomaly_deg,
// mean_motion_rev_day, element_set_no, rev_at_epoch], …]}]}: numbers exactly as the propagator
// had them (JSON doubles round-trip), where TLE text would cut digits and cannot hold NORAD
// numbers past 99999.

#include <string>
#include <string_view>
#include <vector>

#include "azt/orbit/elements.hpp"
#include "azt/util/result.hpp"

namespace azt::app {

struct CachedSource {
  std::string url;
  double last_ok_unix_s = 0.0;
  std::vector<orbit::Elements> sets;
};

std::string element_cache_text(const std::vector<CachedSource>& sources);
/// The sources of a cache file; an error for a file that is not one (the caller logs it and
/// starts without: the cache only saves a download).
Result<std::vector<CachedSource>> read_element_cache(std::string_view text);

/// The whole of `path` when it is at most `max_bytes` (a cache of a large catalogue passes the
/// 4 MiB cap of linux_os::read_file).
Result<std::string> read_text_file(const std::string& path, std::size_t max_bytes);

}  // namespace azt::app
