#include "azt/eme/libration.hpp"
#include "azt/util/angles.hpp"

#include <array>
#include <cmath>

namespace azt::eme {
namespace {

constexpr double kJ2000Jd = 2451545.0;
constexpr double kDaysPerCentury = 36525.0;
constexpr double kWidthHzPerGhzDegPerMin = 0.5 * 6741.0;  // WSJT-X lib/astro0.f90

double sind(double deg) { return std::sin(deg * kRadPerDeg); }
double cosd(double deg) { return std::cos(deg * kRadPerDeg); }

/// The Moon's orientation at `d` days from J2000 (TDB): pole RA α₀, Dec δ₀ and prime meridian W,
/// degrees (Archinal et al. 2011, Table 2, the Moon).
struct Orientation {
  double ra0 = 0.0;
  double dec0 = 0.0;
  double w = 0.0;
};

Orientation moon_orientation(double d) {
  const double t = d / kDaysPerCentury;
  const std::array<double, 13> e = {
      125.045 - 0.0529921 * d,  250.089 - 0.1059842 * d, 260.008 + 13.0120009 * d,
      176.625 + 13.3407154 * d, 357.529 + 0.9856003 * d, 311.589 + 26.4057084 * d,
      134.963 + 13.0649930 * d, 276.617 + 0.3287146 * d, 34.226 + 1.7484877 * d,
      15.134 - 0.1589763 * d,   119.743 + 0.0036096 * d, 239.961 + 0.1643573 * d,
      25.053 + 12.9590088 * d};
  Orientation o;
  o.ra0 = 269.9949 + 0.0031 * t - 3.8787 * sind(e[0]) - 0.1204 * sind(e[1]) + 0.0700 * sind(e[2]) -
          0.0172 * sind(e[3]) + 0.0072 * sind(e[5]) - 0.0052 * sind(e[9]) + 0.0043 * sind(e[12]);
  o.dec0 = 66.5392 + 0.0130 * t + 1.5419 * cosd(e[0]) + 0.0239 * cosd(e[1]) - 0.0278 * cosd(e[2]) +
           0.0068 * cosd(e[3]) - 0.0029 * cosd(e[5]) + 0.0009 * cosd(e[6]) + 0.0008 * cosd(e[9]) -
           0.0009 * cosd(e[12]);
  o.w = 38.3213 + 13.17635815 * d - 1.4e-12 * d * d + 3.5610 * sind(e[0]) + 0.1208 * sind(e[1]) -
        0.0642 * sind(e[2]) + 0.0158 * sind(e[3]) + 0.0252 * sind(e[4]) - 0.0066 * sind(e[5]) -
        0.0047 * sind(e[6]) - 0.0046 * sind(e[7]) + 0.0028 * sind(e[8]) + 0.0052 * sind(e[9]) +
        0.0040 * sind(e[10]) + 0.0019 * sind(e[11]) - 0.0044 * sind(e[12]);
  return o;
}

/// `a` − `b` wrapped to (−180, 180].
double wrapped(double a, double b) { return std::remainder(a - b, 360.0); }

}  // namespace

Libration apparent_libration(const astro::Place& moon, double tt_jd) {
  const Orientation o = moon_orientation(tt_jd - kJ2000Jd);
  // From the Moon's centre towards the observer: the line of sight reversed.
  const std::array<double, 3> v = {-cosd(moon.dec_deg) * cosd(moon.ra_deg),
                                   -cosd(moon.dec_deg) * sind(moon.ra_deg), -sind(moon.dec_deg)};
  // Into the Moon's body frame: Rz(W)·Rx(90° − δ₀)·Rz(90° + α₀).
  const double a = 90.0 + o.ra0;
  const std::array<double, 3> v1 = {cosd(a) * v[0] + sind(a) * v[1],
                                    -sind(a) * v[0] + cosd(a) * v[1], v[2]};
  const double inc = 90.0 - o.dec0;
  const std::array<double, 3> v2 = {v1[0], cosd(inc) * v1[1] + sind(inc) * v1[2],
                                    -sind(inc) * v1[1] + cosd(inc) * v1[2]};
  const std::array<double, 3> v3 = {cosd(o.w) * v2[0] + sind(o.w) * v2[1],
                                    -sind(o.w) * v2[0] + cosd(o.w) * v2[1], v2[2]};
  Libration l;
  l.lon_deg = std::atan2(v3[1], v3[0]) / kRadPerDeg;
  l.lat_deg = std::asin(std::fmax(-1.0, std::fmin(1.0, v3[2]))) / kRadPerDeg;
  return l;
}

double self_echo_width_hz(const Libration& now, const Libration& minute_later, double freq_mhz) {
  const double dl = wrapped(minute_later.lon_deg, now.lon_deg);
  const double db = minute_later.lat_deg - now.lat_deg;
  return kWidthHzPerGhzDegPerMin * (freq_mhz / 1000.0) * 2.0 * std::hypot(dl, db);
}

double dx_echo_width_hz(const Libration& own_now, const Libration& own_later,
                        const Libration& dx_now, const Libration& dx_later, double freq_mhz) {
  const double dl =
      wrapped(own_later.lon_deg, own_now.lon_deg) + wrapped(dx_later.lon_deg, dx_now.lon_deg);
  const double db = (own_later.lat_deg - own_now.lat_deg) + (dx_later.lat_deg - dx_now.lat_deg);
  return kWidthHzPerGhzDegPerMin * (freq_mhz / 1000.0) * std::hypot(dl, db);
}

}  // namespace azt::eme
