#include "azt/calibration/pointing_model.hpp"

#include <algorithm>
#include <cmath>

#include "azt/control/axis_geometry.hpp"
#include "azt/util/angles.hpp"

namespace azt::calibration {
namespace {

/// Within this of the zenith the azimuth correction is held (see corrected_reading).
constexpr double kZenithHoldDeg = 5.0;

using Vec = std::array<double, 3>;  // east, north, up

Vec operator*(double s, const Vec& v) { return {s * v[0], s * v[1], s * v[2]}; }
Vec operator+(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec direction(double az_deg, double el_deg) {
  const double az = az_deg * kRadPerDeg, el = el_deg * kRadPerDeg;
  return {std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
}

using control::wrap_360;

double wrap_180(double deg) { return wrap_360(deg + 180.0) - 180.0; }

control::AzEl to_az_el(const Vec& v) {
  const double horizontal = std::hypot(v[0], v[1]);  // atan2 needs no unit vector
  return {wrap_360(std::atan2(v[0], v[1]) / kRadPerDeg), std::atan2(v[2], horizontal) / kRadPerDeg};
}

/// Rodrigues' rotation of v about the unit axis k by angle (radians).
Vec rotate(const Vec& v, const Vec& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * cross(k, v) + ((1.0 - c) * dot(k, v)) * k;
}

/// The beam in the frame of an untilted azimuth axis: azimuth α, elevation ε as the mount turns
/// them, the elevation axis raised at its clockwise end by NPAE, the beam set CA off square to
/// it and drooping by SAG·cos ε.
Vec beam_on_base(double alpha_deg, double eps_deg, const PointingTerms& t) {
  const double alpha = alpha_deg * kRadPerDeg;
  const double eps = (eps_deg - t.sag_deg * std::cos(eps_deg * kRadPerDeg)) * kRadPerDeg;
  const Vec forward{std::sin(alpha), std::cos(alpha), 0.0};
  const Vec right{std::cos(alpha), -std::sin(alpha), 0.0};
  const Vec up{0.0, 0.0, 1.0};
  const double n = t.npae_deg * kRadPerDeg, c = t.ca_deg * kRadPerDeg;
  const Vec el_axis = std::cos(n) * right + std::sin(n) * up;
  const Vec raised = cross(el_axis, forward);  // "up" in the beam's plane: the zenith when n = 0
  return std::cos(c) * (std::cos(eps) * forward + std::sin(eps) * raised) + std::sin(c) * el_axis;
}

/// The base frame tilted: its up axis leans by hypot(AN, AW) towards north by AN, east by AW.
Vec tilt(const Vec& v, const PointingTerms& t) {
  const double north = t.an_deg * kRadPerDeg, east = t.aw_deg * kRadPerDeg;
  const double angle = std::hypot(north, east);
  if (angle == 0.0) return v;
  const Vec toward{east / angle, north / angle, 0.0};
  const Vec axis = cross(Vec{0.0, 0.0, 1.0}, toward);  // turning about it takes up towards `toward`
  return rotate(v, axis, angle);
}

/// The sky direction `sky` as a reading of the mount's frame nearest `mount`: as it is, or over
/// the zenith (azimuth + 180°, elevation 180° − E).
control::AzEl in_mount_frame(const control::AzEl& sky, const control::AzEl& mount) {
  const control::AzEl over{wrap_360(sky.az_deg + 180.0), 180.0 - sky.el_deg};
  const double d_direct = std::fabs(wrap_180(sky.az_deg - mount.az_deg));
  const double d_over = std::fabs(wrap_180(over.az_deg - mount.az_deg));
  const control::AzEl& chosen = d_over < d_direct ? over : sky;
  return {mount.az_deg + wrap_180(chosen.az_deg - mount.az_deg), chosen.el_deg};
}

}  // namespace

std::array<double, PointingTerms::kCount> PointingTerms::as_array() const {
  return {ia_deg, ie_deg, ca_deg, npae_deg, an_deg, aw_deg, sag_deg};
}

PointingTerms PointingTerms::from_array(const std::array<double, kCount>& v) {
  PointingTerms t;
  t.ia_deg = v[0];
  t.ie_deg = v[1];
  t.ca_deg = v[2];
  t.npae_deg = v[3];
  t.an_deg = v[4];
  t.aw_deg = v[5];
  t.sag_deg = v[6];
  return t;
}

bool PointingTerms::is_zero() const {
  const auto v = as_array();
  return std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; });
}

PointingTerms tilt_terms(double tilt_deg, double toward_deg) {
  PointingTerms t;
  t.an_deg = tilt_deg * std::cos(toward_deg * kRadPerDeg);
  t.aw_deg = tilt_deg * std::sin(toward_deg * kRadPerDeg);
  return t;
}

control::AzEl beam_on_sky(const control::AzEl& mount, const PointingTerms& terms) {
  const Vec base = beam_on_base(mount.az_deg - terms.ia_deg, mount.el_deg - terms.ie_deg, terms);
  return to_az_el(tilt(base, terms));
}

std::optional<control::AzEl> mount_for_sky(const control::AzEl& sky, const PointingTerms& terms) {
  control::AzEl mount = sky;
  for (int i = 0; i < 50; ++i) {
    const control::AzEl beam = in_mount_frame(beam_on_sky(mount, terms), mount);
    const double d_az = wrap_180(sky.az_deg - beam.az_deg), d_el = sky.el_deg - beam.el_deg;
    mount.az_deg += d_az;
    mount.el_deg += d_el;
    if (std::fabs(d_az) < 1e-10 && std::fabs(d_el) < 1e-10) {
      return control::AzEl{wrap_360(mount.az_deg), mount.el_deg};
    }
  }
  return std::nullopt;
}

control::AzEl corrected_reading(const control::AzEl& mount, const PointingTerms& terms) {
  if (terms.is_zero()) return mount;
  const control::AzEl beam = in_mount_frame(beam_on_sky(mount, terms), mount);
  const double from_zenith = mount.el_deg - 90.0;
  if (std::fabs(from_zenith) >= kZenithHoldDeg) return beam;
  const control::AzEl held{
      mount.az_deg, 90.0 + std::copysign(kZenithHoldDeg, from_zenith == 0.0 ? -1.0 : from_zenith)};
  const control::AzEl held_beam = in_mount_frame(beam_on_sky(held, terms), held);
  return {mount.az_deg + (held_beam.az_deg - held.az_deg), beam.el_deg};
}

double separation_deg(const control::AzEl& a, const control::AzEl& b) {
  const Vec u = direction(a.az_deg, a.el_deg), v = direction(b.az_deg, b.el_deg);
  const Vec c = cross(u, v);
  return std::atan2(std::sqrt(dot(c, c)), dot(u, v)) / kRadPerDeg;
}

namespace {

/// The tangent plane at `source`: unit vectors of increasing azimuth and elevation there.
struct TangentPlane {
  Vec centre;
  Vec along_az;
  Vec along_el;
};

TangentPlane tangent_plane(const control::AzEl& source) {
  const double az = source.az_deg * kRadPerDeg, el = source.el_deg * kRadPerDeg;
  return {direction(source.az_deg, source.el_deg),
          {std::cos(az), -std::sin(az), 0.0},
          {-std::sin(el) * std::sin(az), -std::sin(el) * std::cos(az), std::cos(el)}};
}

}  // namespace

SkyOffset offset_between(const control::AzEl& source, const control::AzEl& beam) {
  const TangentPlane t = tangent_plane(source);
  const Vec b = direction(beam.az_deg, beam.el_deg);
  const double depth = dot(b, t.centre);
  return {std::atan(dot(b, t.along_az) / depth) / kRadPerDeg,
          std::atan(dot(b, t.along_el) / depth) / kRadPerDeg};
}

control::AzEl apply_offset(const control::AzEl& source, const SkyOffset& offset) {
  const TangentPlane t = tangent_plane(source);
  const double xi = std::tan(offset.xel_deg * kRadPerDeg);
  const double eta = std::tan(offset.el_deg * kRadPerDeg);
  return to_az_el(t.centre + xi * t.along_az + eta * t.along_el);  // to_az_el normalises
}

}  // namespace azt::calibration
