#pragma once
// A path through sets of allowed positions, one set per sample, no faster than a rate
// (docs/satellites.md). The pass planner asks "can the azimuth keep the beam within e of the
// satellite at every moment?": each moment allows a few intervals of azimuth (one per turn of the
// travel, or per half turn on a flip mount), and the mount can only move so far between moments.
// Forward reachability answers it exactly (the reachable set stays a union of intervals), and a
// path is then read backwards through the reachable sets, as close as each moment allows to where
// the caller would like it.

#include <functional>
#include <optional>
#include <vector>

namespace azt::track {

struct Span {
  double lo = 0.0;
  double hi = 0.0;
};
/// Disjoint spans in increasing order; empty means nowhere.
using Spans = std::vector<Span>;

/// Every position within `by` of a position in `s`.
Spans widened(const Spans& s, double by);
/// The positions in both.
Spans intersection(const Spans& a, const Spans& b);
/// The distance between the nearest points of two span sets (0 when they meet; infinite when
/// either is empty).
double gap(const Spans& a, const Spans& b);

/// Where a path starting in `start` and moving no faster than `rate` per unit of t can be at each
/// sample while staying in `allowed` (sample times `t`, increasing). Once a sample is unreachable
/// it and every later sample are empty.
std::vector<Spans> reachable_forward(const std::vector<double>& t,
                                     const std::vector<Spans>& allowed, double rate,
                                     const Spans& start);
/// The same, backwards from the last sample (where a path ending anywhere allowed can come from).
std::vector<Spans> reachable_backward(const std::vector<double>& t,
                                      const std::vector<Spans>& allowed, double rate);

/// The preferred point of [lo, hi] at sample i and how much it is disliked (lower is better);
/// `next` is the point chosen for the sample after (none for the last).
using Preference = std::function<std::pair<double, double>(std::size_t i, Span within,
                                                           std::optional<double> next)>;

/// A path through forward-reachable sets (none empty), chosen from the last sample backwards:
/// at each sample the preferred point among those within rate of the next one.
std::vector<double> path_through(const std::vector<double>& t, const std::vector<Spans>& reach,
                                 double rate, const Preference& prefer);

}  // namespace azt::track
