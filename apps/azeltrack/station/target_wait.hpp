#pragma once
// Waiting, said plainly: while TRACK's target is below the horizon limit the station holds, and
// this says until when (docs/daemon.md "Who is in control"): the instant the target rises
// through the limit, found by astro::next_reachable over the next two days on the worker
// thread (some 600 sky computations: tens of milliseconds, never on the loop), with an
// ephemeris of its own (ERFA's, which shares no state with the loop's), once per target and
// again when that instant has passed.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "azt/astro/target.hpp"
#include "common/off_loop.hpp"
#include "config/sky_config.hpp"

namespace azt::app {

struct TargetWaitParts {
  const SkyConfig& sky;     ///< the running station: place, atmosphere
  double min_el_deg = 0.0;  ///< the horizon limit the modes hold below ([geometry] el_min_deg)
  Offload offload;
};

class TargetWait {
 public:
  explicit TargetWait(TargetWaitParts parts) : p_(std::move(parts)) {}

  /// /api/state `target.waiting`: null unless `target` (TRACK's, nullopt otherwise) is below the
  /// limit at `el_deg`; then {reason, until (UTC, null while searching or when it does not rise
  /// within two days), in_s}. Starts the search when none is known for this target.
  nlohmann::json waiting(const std::optional<astro::Target>& target, double el_deg,
                         double now_unix_s);

 private:
  void search(const astro::Target& target, double from_unix_s);

  TargetWaitParts p_;
  std::string searched_for_;  ///< the target's name the answer is for ("" none)
  bool busy_ = false;
  std::optional<double> until_;  ///< when it rises; nullopt: not within the span
  std::string error_;            ///< the sky could not be computed
};

}  // namespace azt::app
