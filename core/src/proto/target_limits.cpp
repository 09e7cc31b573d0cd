#include "azt/proto/target_limits.hpp"

#include "azt/util/format_number.hpp"

namespace azt::proto {
namespace {

std::string outside(const char* axis, double deg, double min_deg, double max_deg) {
  return std::string(axis) + " " + format_number(deg) + "° is outside " + format_number(min_deg) +
         "° to " + format_number(max_deg) + "°";
}

}  // namespace

std::string TargetLimits::why_not_az(double az_deg) const {
  return accepts_az(az_deg) ? "" : outside("az", az_deg, az_min_deg, az_max_deg);
}

std::string TargetLimits::why_not_el(double el_deg) const {
  return accepts_el(el_deg) ? "" : outside("el", el_deg, el_min_deg, el_max_deg);
}

}  // namespace azt::proto
