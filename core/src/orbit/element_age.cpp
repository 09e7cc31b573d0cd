// The element-age verdict (azt/orbit/element_age.hpp).
#include "azt/orbit/element_age.hpp"

#include <cmath>
#include <string>

namespace azt::orbit {

ElementAge judge_element_age(double age_days, const ElementAgeLimits& limits) {
  const double magnitude = std::fabs(age_days);
  if (!(magnitude <= limits.refuse_days)) return ElementAge::Refused;  // NaN too
  if (magnitude > limits.stale_days) return ElementAge::Stale;
  return ElementAge::Fresh;
}

std::string element_age_refusal(const std::string& name, double age_days,
                                const ElementAgeLimits& limits) {
  if (judge_element_age(age_days, limits) != ElementAge::Refused) return "";
  const auto tenths = [](double v) {
    const long t = std::lround(std::fabs(v) * 10.0);
    return std::string(v < 0.0 ? "-" : "") + std::to_string(t / 10) + "." + std::to_string(t % 10);
  };
  return "the elements of " + name + " are " + tenths(age_days) +
         " days from their epoch (beyond [satellites] refuse_days = " +
         std::to_string(std::lround(limits.refuse_days)) + "): not tracked; fetch fresh ones";
}

}  // namespace azt::orbit
