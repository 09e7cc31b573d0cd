#include "azt/astro/tabulated_ephemeris.hpp"

#include <algorithm>
#include <cmath>

#include "azt/astro/hermite.hpp"
#include "azt/util/format_number.hpp"

namespace azt::astro {
namespace {

constexpr double kMaxNodes = 100000.0;

}  // namespace

Result<TabulatedEphemeris> TabulatedEphemeris::build(const Ephemeris& source,
                                                     const JulianDate& start_tt, double span_days,
                                                     double step_days) {
  if (!std::isfinite(span_days) || span_days <= 0.0 || !std::isfinite(step_days) ||
      step_days <= 0.0) {
    return fail("ephemeris table: span and step must be positive");
  }
  const double intervals = std::ceil(span_days / step_days);
  if (intervals + 1.0 > kMaxNodes) {
    return fail("ephemeris table: " + format_number(intervals + 1.0) + " nodes is too many");
  }
  TabulatedEphemeris table;
  table.name_ = source.name();
  table.start_ = start_tt;
  table.step_days_ = step_days;
  const auto count = static_cast<std::size_t>(intervals) + 1;
  table.nodes_.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const JulianDate tt{start_tt.jd1, start_tt.jd2 + static_cast<double>(k) * step_days};
    auto earth_sun = source.earth_sun(tt);
    if (!earth_sun) return earth_sun.error();
    auto moon = source.moon_geocentric(tt);
    if (!moon) return moon.error();
    table.nodes_.push_back(Node{earth_sun->earth_bary, earth_sun->sun_bary, *moon});
  }
  return table;
}

bool TabulatedEphemeris::covers(const JulianDate& tt) const { return locate(tt).ok(); }

Result<TabulatedEphemeris::Where> TabulatedEphemeris::locate(const JulianDate& tt) const {
  // Difference the parts separately: keeps sub-microsecond resolution.
  const double offset_days = (tt.jd1 - start_.jd1) + (tt.jd2 - start_.jd2);
  const double position = offset_days / step_days_;
  const double last = static_cast<double>(nodes_.size() - 1);
  if (!std::isfinite(position) || position < 0.0 || position > last) {
    return fail("ephemeris table does not cover TT JD " + format_number(tt.total()));
  }
  const double index = std::min(std::floor(position), last - 1.0);
  return Where{static_cast<std::size_t>(index), position - index};
}

Result<EarthSun> TabulatedEphemeris::earth_sun(const JulianDate& tt) const {
  auto where = locate(tt);
  if (!where) return where.error();
  const Node& a = nodes_[where->index];
  const Node& b = nodes_[where->index + 1];
  return EarthSun{hermite(a.earth, b.earth, step_days_, where->fraction),
                  hermite(a.sun, b.sun, step_days_, where->fraction)};
}

Result<PosVel> TabulatedEphemeris::moon_geocentric(const JulianDate& tt) const {
  auto where = locate(tt);
  if (!where) return where.error();
  return hermite(nodes_[where->index].moon, nodes_[where->index + 1].moon, step_days_,
                 where->fraction);
}

}  // namespace azt::astro
