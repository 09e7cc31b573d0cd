#include "azt/eme/polarisation.hpp"
#include "azt/util/angles.hpp"

#include <cmath>

namespace azt::eme {
namespace {

constexpr double kMnrFloor = 0.056234;  // 10^(−25/20): MNR is shown up to 25 dB

}  // namespace

double parallactic_angle_deg(double lat_deg, double az_deg, double el_deg) {
  const double lat = lat_deg * kRadPerDeg;
  const double az = az_deg * kRadPerDeg;
  const double el = el_deg * kRadPerDeg;
  const double y = std::cos(lat) * std::sin(az);
  const double x = std::sin(lat) * std::cos(el) - std::cos(lat) * std::cos(az) * std::sin(el);
  return std::atan2(y, x) / kRadPerDeg;
}

double dpol_deg(double own_parallactic_deg, double dx_parallactic_deg) {
  double d = std::fmod(dx_parallactic_deg - own_parallactic_deg + 720.0, 180.0);
  if (d < 0.0) d += 180.0;
  return d > 90.0 ? d - 180.0 : d;
}

double mnr_db(double dpol) {
  const double x = std::fmax(std::fabs(std::cos(2.0 * dpol * kRadPerDeg)), kMnrFloor);
  return -20.0 * std::log10(x);
}

}  // namespace azt::eme
