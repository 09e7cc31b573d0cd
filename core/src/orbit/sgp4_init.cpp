// SGP4 initialisation (Vallado et al. 2006, sgp4init and initl): from TLE units to the model's
// constants. Expressions keep the reference's operand order: the verification set is matched
// to 1e-6 km only if the rounding is the same.

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "azt/orbit/sgp4.hpp"
#include "azt/util/angles.hpp"
#include "sgp4_internal.hpp"

namespace azt::orbit {

namespace sgp4_detail {

const Gravity& wgs72() {
  static const Gravity gravity = [] {
    Gravity g{};
    g.radius_km = 6378.135;
    g.mu_km3_s2 = 398600.8;
    g.xke = 60.0 / std::sqrt(g.radius_km * g.radius_km * g.radius_km / g.mu_km3_s2);
    g.j2 = 0.001082616;
    g.j3 = -0.00000253881;
    g.j4 = -0.00000165597;
    g.j3oj2 = g.j3 / g.j2;
    return g;
  }();
  return gravity;
}

double gmst_1982(double jd_ut1) {
  const double tut1 = (jd_ut1 - 2451545.0) / 36525.0;
  // Seconds of sidereal time (Aoki et al. 1982), then 1/240 to degrees.
  double temp = -6.2e-6 * tut1 * tut1 * tut1 + 0.093104 * tut1 * tut1 +
                (876600.0 * 3600 + 8640184.812866) * tut1 + 67310.54841;
  temp = std::fmod(temp * kRadPerDeg / 240.0, kTwoPi);
  if (temp < 0.0) temp += kTwoPi;
  return temp;
}

}  // namespace sgp4_detail

namespace {

using sgp4_detail::kTwoPi;
using sgp4_detail::kTwoThirds;
using sgp4_detail::wgs72;

/// What initl derives and sgp4init goes on using.
struct InitlTerms {
  double ao, con42, cosio, cosio2, eccsq, omeosq, posq, rp, rteosq, sinio;
};

/// initl: un-Kozai the mean motion (Brouwer's), the semi-major axis and the usual inclination
/// and eccentricity functions; the sidereal angle at epoch.
InitlTerms initl(Sgp4Model& m) {
  const auto& g = wgs72();
  InitlTerms t{};
  t.eccsq = m.ecco * m.ecco;
  t.omeosq = 1.0 - t.eccsq;
  t.rteosq = std::sqrt(t.omeosq);
  t.cosio = std::cos(m.inclo);
  t.cosio2 = t.cosio * t.cosio;
  const double ak = std::pow(g.xke / m.no_kozai, kTwoThirds);
  const double d1 = 0.75 * g.j2 * (3.0 * t.cosio2 - 1.0) / (t.rteosq * t.omeosq);
  double del = d1 / (ak * ak);
  const double adel = ak * (1.0 - del * del - del * (1.0 / 3.0 + 134.0 * del * del / 81.0));
  del = d1 / (adel * adel);
  m.no_unkozai = m.no_kozai / (1.0 + del);
  t.ao = std::pow(g.xke / m.no_unkozai, kTwoThirds);
  t.sinio = std::sin(m.inclo);
  const double po = t.ao * t.omeosq;
  t.con42 = 1.0 - 5.0 * t.cosio2;
  m.con41 = -t.con42 - t.cosio2 - t.cosio2;
  t.posq = po * po;
  t.rp = t.ao * (1.0 - m.ecco);
  m.gsto = sgp4_detail::gmst_1982(m.epoch_days_1950 + 2433281.5);
  return t;
}

/// The atmosphere's s and q0−s⁴ for the perigee height (Spacetrack Report #3: s = 78 km above
/// the surface, lowered for perigees under 156 km, floored at 20 km).
struct DragHeight {
  double sfour, qzms24;
};
DragHeight drag_height(double rp) {
  const double re = wgs72().radius_km;
  const auto fourth = [](double x) { return x * x * x * x; };
  DragHeight h{78.0 / re + 1.0, fourth((120.0 - 78.0) / re)};
  const double perige = (rp - 1.0) * re;
  if (perige < 156.0) {
    double sfour = perige - 78.0;
    if (perige < 98.0) sfour = 20.0;
    h.qzms24 = fourth((120.0 - sfour) / re);
    h.sfour = sfour / re + 1.0;
  }
  return h;
}

/// The drag coefficients C1, C4, C5 and the secular mean-anomaly, perigee and node rates.
/// Returns what the d2…t5cof step needs.
struct DragTerms {
  double ao, tsi, sfour;
};
DragTerms init_near_earth(Sgp4Model& m, const InitlTerms& t) {
  const auto& g = wgs72();
  const DragHeight h = drag_height(t.rp);
  const double pinvsq = 1.0 / t.posq;
  const double tsi = 1.0 / (t.ao - h.sfour);
  m.eta = t.ao * m.ecco * tsi;
  const double etasq = m.eta * m.eta;
  const double eeta = m.ecco * m.eta;
  const double psisq = std::fabs(1.0 - etasq);
  const double coef = h.qzms24 * std::pow(tsi, 4.0);
  const double coef1 = coef / std::pow(psisq, 3.5);
  const double cc2 = coef1 * m.no_unkozai *
                     (t.ao * (1.0 + 1.5 * etasq + eeta * (4.0 + etasq)) +
                      0.375 * g.j2 * tsi / psisq * m.con41 * (8.0 + 3.0 * etasq * (8.0 + etasq)));
  m.cc1 = m.bstar * cc2;
  double cc3 = 0.0;
  if (m.ecco > 1.0e-4) cc3 = -2.0 * coef * tsi * g.j3oj2 * m.no_unkozai * t.sinio / m.ecco;
  m.x1mth2 = 1.0 - t.cosio2;
  m.cc4 = 2.0 * m.no_unkozai * coef1 * t.ao * t.omeosq *
          (m.eta * (2.0 + 0.5 * etasq) + m.ecco * (0.5 + 2.0 * etasq) -
           g.j2 * tsi / (t.ao * psisq) *
               (-3.0 * m.con41 * (1.0 - 2.0 * eeta + etasq * (1.5 - 0.5 * eeta)) +
                0.75 * m.x1mth2 * (2.0 * etasq - eeta * (1.0 + etasq)) * std::cos(2.0 * m.argpo)));
  m.cc5 = 2.0 * coef1 * t.ao * t.omeosq * (1.0 + 2.75 * (etasq + eeta) + eeta * etasq);
  const double cosio4 = t.cosio2 * t.cosio2;
  const double temp1 = 1.5 * g.j2 * pinvsq * m.no_unkozai;
  const double temp2 = 0.5 * temp1 * g.j2 * pinvsq;
  const double temp3 = -0.46875 * g.j4 * pinvsq * pinvsq * m.no_unkozai;
  m.mdot = m.no_unkozai + 0.5 * temp1 * t.rteosq * m.con41 +
           0.0625 * temp2 * t.rteosq * (13.0 - 78.0 * t.cosio2 + 137.0 * cosio4);
  m.argpdot = (-0.5 * temp1 * t.con42 + 0.0625 * temp2 * (7.0 - 114.0 * t.cosio2 + 395.0 * cosio4) +
               temp3 * (3.0 - 36.0 * t.cosio2 + 49.0 * cosio4));
  const double xhdot1 = -temp1 * t.cosio;
  m.nodedot =
      xhdot1 +
      (0.5 * temp2 * (4.0 - 19.0 * t.cosio2) + 2.0 * temp3 * (3.0 - 7.0 * t.cosio2)) * t.cosio;
  m.omgcof = m.bstar * cc3 * std::cos(m.argpo);
  m.xmcof = 0.0;
  if (m.ecco > 1.0e-4) m.xmcof = -kTwoThirds * coef * m.bstar / eeta;
  m.nodecf = 3.5 * t.omeosq * xhdot1 * m.cc1;
  m.t2cof = 1.5 * m.cc1;
  return DragTerms{t.ao, tsi, h.sfour};
}

/// Long-period J3 coefficients and the mean-anomaly reference values.
void init_long_period(Sgp4Model& m, const InitlTerms& t) {
  const auto& g = wgs72();
  // Guard against division by zero for an inclination of exactly 180°.
  constexpr double kTemp4 = 1.5e-12;
  const double divisor = std::fabs(t.cosio + 1.0) > kTemp4 ? 1.0 + t.cosio : kTemp4;
  m.xlcof = -0.25 * g.j3oj2 * t.sinio * (3.0 + 5.0 * t.cosio) / divisor;
  m.aycof = -0.5 * g.j3oj2 * t.sinio;
  const double delmotemp = 1.0 + m.eta * std::cos(m.mo);
  m.delmo = delmotemp * delmotemp * delmotemp;
  m.sinmao = std::sin(m.mo);
  m.x7thm1 = 7.0 * t.cosio2 - 1.0;
}

/// The higher-order drag terms, for near-earth orbits with perigee above 220 km.
void init_higher_drag(Sgp4Model& m, const DragTerms& d) {
  const double cc1sq = m.cc1 * m.cc1;
  m.d2 = 4.0 * d.ao * d.tsi * cc1sq;
  const double temp = m.d2 * d.tsi * m.cc1 / 3.0;
  m.d3 = (17.0 * d.ao + d.sfour) * temp;
  m.d4 = 0.5 * temp * d.ao * d.tsi * (221.0 * d.ao + 31.0 * d.sfour) * m.cc1;
  m.t3cof = m.d2 + 2.0 * cc1sq;
  m.t4cof = 0.25 * (3.0 * m.d3 + m.cc1 * (12.0 * m.d2 + 10.0 * cc1sq));
  m.t5cof = 0.2 * (3.0 * m.d4 + 12.0 * m.cc1 * m.d3 + 6.0 * m.d2 * m.d2 +
                   15.0 * cc1sq * (2.0 * m.d2 + cc1sq));
}

Result<bool> validate(const Elements& e) {
  const double values[] = {e.epoch_jd,        e.epoch_jd_frac,    e.bstar,
                           e.inclination_deg, e.raan_deg,         e.eccentricity,
                           e.arg_perigee_deg, e.mean_anomaly_deg, e.mean_motion_rev_day};
  for (double v : values) {
    if (!std::isfinite(v)) return fail(e.label() + ": an element is not a finite number");
  }
  if (e.eccentricity < 0.0 || e.eccentricity >= 1.0) {
    return fail(e.label() + ": eccentricity out of range 0 ≤ e < 1");
  }
  if (e.mean_motion_rev_day <= 0.0) return fail(e.label() + ": mean motion ≤ 0");
  if (e.inclination_deg < 0.0 || e.inclination_deg > 180.0) {
    return fail(e.label() + ": inclination out of range 0–180°");
  }
  return true;
}

}  // namespace

Sgp4::Sgp4(Elements elements, const Sgp4Model& model)
    : elements_(std::move(elements)), model_(model) {}

Result<Sgp4> Sgp4::make(const Elements& elements) {
  if (Result<bool> ok = validate(elements); !ok) return ok.error();
  // rad/min per rev/day, written as the reference writes it (1440 / 2π, then a division).
  constexpr double kXpdotp = 1440.0 / (2.0 * std::numbers::pi);
  Sgp4Model m;
  m.epoch_days_1950 = (elements.epoch_jd + elements.epoch_jd_frac) - 2433281.5;
  m.bstar = elements.bstar;
  m.ecco = elements.eccentricity;
  m.argpo = elements.arg_perigee_deg * kRadPerDeg;
  m.inclo = elements.inclination_deg * kRadPerDeg;
  m.mo = elements.mean_anomaly_deg * kRadPerDeg;
  m.nodeo = elements.raan_deg * kRadPerDeg;
  m.no_kozai = elements.mean_motion_rev_day / kXpdotp;

  const InitlTerms t = initl(m);
  m.simple = t.rp < 220.0 / wgs72().radius_km + 1.0;
  const DragTerms drag = init_near_earth(m, t);
  init_long_period(m, t);
  if (kTwoPi / m.no_unkozai >= 225.0) {
    m.deep = true;
    m.simple = true;
    sgp4_detail::init_deep_space(m);
  }
  if (!m.simple) init_higher_drag(m, drag);
  return Sgp4(elements, m);
}

}  // namespace azt::orbit
