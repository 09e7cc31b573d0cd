#include "azt/astro/rise_search.hpp"

#include <cmath>

namespace azt::astro {
namespace {

/// The crossing between `before` (not reachable) and `after` (reachable), to `tolerance_s`.
Result<double> crossing(const ReachableAt& reachable, double before, double after,
                        double tolerance_s) {
  while (after - before > tolerance_s) {
    const double mid = 0.5 * (before + after);
    const auto r = reachable(mid);
    if (!r) return r.error();
    (*r ? after : before) = mid;
  }
  return after;
}

}  // namespace

Result<std::optional<double>> next_reachable(const ReachableAt& reachable, double from_unix_s,
                                             const RiseSearch& search) {
  if (!(search.step_s > 0.0) || !(search.span_s > 0.0) || !(search.tolerance_s > 0.0)) {
    return fail("the rise search needs a positive step, span and tolerance");
  }
  const auto now = reachable(from_unix_s);
  if (!now) return now.error();
  if (*now) return std::optional<double>(from_unix_s);
  double before = from_unix_s;
  const double end = from_unix_s + search.span_s;
  while (before < end) {
    const double after = std::fmin(before + search.step_s, end);
    const auto r = reachable(after);
    if (!r) return r.error();
    if (*r) {
      auto t = crossing(reachable, before, after, search.tolerance_s);
      if (!t) return t.error();
      return std::optional<double>(*t);
    }
    before = after;
  }
  return std::optional<double>();
}

}  // namespace azt::astro
