#include "azt/hands/pad_axis.hpp"

#include <algorithm>
#include <cmath>

namespace azt::hands {

double pad_deflection(int value, const PadAxisRange& range, double dead_zone) {
  const double half = (static_cast<double>(range.maximum) - range.minimum) / 2.0;
  if (!(half > 0.0)) return 0.0;
  const double centre = (static_cast<double>(range.maximum) + range.minimum) / 2.0;
  const double x = std::clamp((value - centre) / half, -1.0, 1.0);
  const double zone = std::clamp(std::max(dead_zone, std::fabs(range.flat) / half), 0.0, 0.99);
  if (std::fabs(x) <= zone) return 0.0;
  return std::copysign((std::fabs(x) - zone) / (1.0 - zone), x);
}

}  // namespace azt::hands
