#pragma once
// When a target the station cannot reach now becomes reachable: the first instant after a start
// at which a predicate (the target above the horizon limit and the mask, inside the travel) turns
// true, found by sampling every `step_s` and refining the crossing by bisection. Pure: the
// predicate computes the sky; nothing here knows which target it is.
//
// The step bounds what can be missed: a target that is reachable for less than one step between
// two samples is not seen. At 300 s the Moon's elevation changes by at most 1.3° and the Sun's
// by 1.25° (15°/h at the equator), so only a graze of the limit is missed, never a rise.

#include <functional>
#include <optional>

#include "azt/util/result.hpp"

namespace azt::astro {

struct RiseSearch {
  double step_s = 300.0;
  /// Beyond this the answer is "not within the span" (a source that never rises here, the Moon
  /// near a standstill at a far-northern station): two days.
  double span_s = 2.0 * 86400.0;
  double tolerance_s = 1.0;
};

/// Whether the target is reachable at a UTC instant (seconds since 1970); an error when the
/// sky cannot be computed then (outside the ephemeris).
using ReachableAt = std::function<Result<bool>(double unix_s)>;

/// The first instant after `from_unix_s` at which `reachable` is true, to `tolerance_s`;
/// `from_unix_s` itself when it is already; nullopt when not within `span_s`.
Result<std::optional<double>> next_reachable(const ReachableAt& reachable, double from_unix_s,
                                             const RiseSearch& search = {});

}  // namespace azt::astro
