#include "azt/track/rate_limited_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace azt::track {

Spans widened(const Spans& s, double by) {
  Spans out;
  for (const Span& x : s) {
    const Span w{x.lo - by, x.hi + by};
    if (!out.empty() && w.lo <= out.back().hi) {
      out.back().hi = std::max(out.back().hi, w.hi);
    } else {
      out.push_back(w);
    }
  }
  return out;
}

Spans intersection(const Spans& a, const Spans& b) {
  Spans out;
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    const double lo = std::max(a[i].lo, b[j].lo);
    const double hi = std::min(a[i].hi, b[j].hi);
    if (lo <= hi) out.push_back({lo, hi});
    if (a[i].hi < b[j].hi) {
      ++i;
    } else {
      ++j;
    }
  }
  return out;
}

double gap(const Spans& a, const Spans& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const Span& x : a) {
    for (const Span& y : b) {
      best = std::min(best, std::max({0.0, y.lo - x.hi, x.lo - y.hi}));
    }
  }
  return best;
}

std::vector<Spans> reachable_forward(const std::vector<double>& t,
                                     const std::vector<Spans>& allowed, double rate,
                                     const Spans& start) {
  std::vector<Spans> reach(allowed.size());
  if (allowed.empty()) return reach;
  reach[0] = intersection(allowed[0], start);
  for (std::size_t i = 1; i < allowed.size() && !reach[i - 1].empty(); ++i) {
    reach[i] = intersection(widened(reach[i - 1], rate * (t[i] - t[i - 1])), allowed[i]);
  }
  return reach;
}

std::vector<Spans> reachable_backward(const std::vector<double>& t,
                                      const std::vector<Spans>& allowed, double rate) {
  std::vector<Spans> reach(allowed.size());
  if (allowed.empty()) return reach;
  reach.back() = allowed.back();
  for (std::size_t i = allowed.size() - 1; i-- > 0 && !reach[i + 1].empty();) {
    reach[i] = intersection(widened(reach[i + 1], rate * (t[i + 1] - t[i])), allowed[i]);
  }
  return reach;
}

std::vector<double> path_through(const std::vector<double>& t, const std::vector<Spans>& reach,
                                 double rate, const Preference& prefer) {
  std::vector<double> path(reach.size());
  std::optional<double> next;
  for (std::size_t i = reach.size(); i-- > 0;) {
    Spans choices = reach[i];
    if (next) {
      // A hair of slack: the reachable sets were widened by the same step, in another order.
      const double step = rate * (t[i + 1] - t[i]) * (1.0 + 1e-12) + 1e-9;
      choices = intersection(choices, Spans{{*next - step, *next + step}});
    }
    double best_cost = std::numeric_limits<double>::infinity();
    for (const Span& s : choices) {
      const auto [at, cost] = prefer(i, s, next);
      if (cost < best_cost) {
        best_cost = cost;
        path[i] = at;
      }
    }
    next = path[i];
  }
  return path;
}

}  // namespace azt::track
