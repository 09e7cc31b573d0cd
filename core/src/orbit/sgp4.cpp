// SGP4 propagation (Vallado et al. 2006, sgp4): secular gravity and drag, the deep-space
// secular and periodic terms, long-period J3 terms, Kepler's equation, short-period J2 terms,
// and the TEME position and velocity. Each step is a function; the error codes 1–6 of the
// reference become messages (5 is no longer used by the 2006 code).

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <system_error>

#include "azt/orbit/sgp4.hpp"
#include "sgp4_internal.hpp"

namespace azt::orbit {

namespace {

using sgp4_detail::DeepMean;
using sgp4_detail::kTwoPi;
using sgp4_detail::kTwoThirds;
using sgp4_detail::Perturbed;
using sgp4_detail::wgs72;

/// `value` with six decimals, for the messages (the reference prints its values so).
std::string fixed6(double value) {
  std::array<char, 64> buf{};
  const auto [end, ec] =
      std::to_chars(buf.data(), buf.data() + buf.size(), value, std::chars_format::fixed, 6);
  return ec == std::errc{} ? std::string(buf.data(), end) : std::string("?");
}

/// Mean elements after the secular terms, with the drag polynomials' a, e and L factors.
struct Secular {
  DeepMean mean;
  double tempa, tempe, templ;
};

/// Secular effects of gravity (J2, J4) and atmospheric drag (C1…C5, D2…D4).
Secular secular_terms(const Sgp4Model& m, double t) {
  const double xmdf = m.mo + m.mdot * t;
  const double argpdf = m.argpo + m.argpdot * t;
  const double nodedf = m.nodeo + m.nodedot * t;
  const double t2 = t * t;
  Secular s{};
  s.mean = DeepMean{m.ecco, argpdf, m.inclo, xmdf, nodedf + m.nodecf * t2, m.no_unkozai};
  s.tempa = 1.0 - m.cc1 * t;
  s.tempe = m.bstar * m.cc4 * t;
  s.templ = m.t2cof * t2;
  if (!m.simple) {
    const double delomg = m.omgcof * t;
    const double delmtemp = 1.0 + m.eta * std::cos(xmdf);
    const double delm = m.xmcof * (delmtemp * delmtemp * delmtemp - m.delmo);
    const double temp = delomg + delm;
    s.mean.mm = xmdf + temp;
    s.mean.argpm = argpdf - temp;
    const double t3 = t2 * t;
    const double t4 = t3 * t;
    s.tempa = s.tempa - m.d2 * t2 - m.d3 * t3 - m.d4 * t4;
    s.tempe = s.tempe + m.bstar * m.cc5 * (std::sin(s.mean.mm) - m.sinmao);
    s.templ = s.templ + m.t3cof * t3 + t4 * (m.t4cof + t * m.t5cof);
  }
  return s;
}

/// The mean elements with drag applied: semi-major axis (Earth radii), mean motion, e, and the
/// angles reduced to one turn.
struct MeanElements {
  double am, nm, em, inclm, argpm, nodem, mm;
};

Result<MeanElements> apply_drag(const Sgp4Model& m, const Secular& s) {
  const auto& g = wgs72();
  const DeepMean& d = s.mean;
  if (d.nm <= 0.0) {
    return fail("mean motion below zero (" + fixed6(d.nm) + " rad/min)");
  }
  MeanElements e{};
  e.am = std::pow((g.xke / d.nm), kTwoThirds) * s.tempa * s.tempa;
  e.nm = g.xke / std::pow(e.am, 1.5);
  e.em = d.em - s.tempe;
  if (e.em >= 1.0 || e.em < -0.001) {
    return fail("mean eccentricity out of range 0 ≤ e < 1 (" + fixed6(e.em) + ")");
  }
  if (e.em < 1.0e-6) e.em = 1.0e-6;
  const double mm = d.mm + m.no_unkozai * s.templ;
  double xlm = mm + d.argpm + d.nodem;
  e.nodem = std::fmod(d.nodem, kTwoPi);
  e.argpm = std::fmod(d.argpm, kTwoPi);
  xlm = std::fmod(xlm, kTwoPi);
  e.mm = std::fmod(xlm - e.argpm - e.nodem, kTwoPi);
  e.inclm = d.inclm;
  return e;
}

/// The elements the long- and short-period terms work on, with the J3 and J2 coefficients of
/// their inclination (deep-space orbits recompute them from the perturbed inclination).
struct Osculating {
  Perturbed p;
  double sinip, cosip, aycof, xlcof, con41, x1mth2, x7thm1;
};

Result<Osculating> periodics(const Sgp4Model& m, const MeanElements& e, double t) {
  Osculating o{};
  o.p = Perturbed{e.em, e.inclm, e.nodem, e.argpm, e.mm};
  o.aycof = m.aycof;
  o.xlcof = m.xlcof;
  o.con41 = m.con41;
  o.x1mth2 = m.x1mth2;
  o.x7thm1 = m.x7thm1;
  if (m.deep) {
    o.p = sgp4_detail::deep_space_periodics(m, t, o.p);
    if (o.p.inclp < 0.0) {
      o.p.inclp = -o.p.inclp;
      o.p.nodep = o.p.nodep + std::numbers::pi;
      o.p.argpp = o.p.argpp - std::numbers::pi;
    }
    if (o.p.ep < 0.0 || o.p.ep > 1.0) {
      return fail("perturbed eccentricity out of range 0 ≤ e ≤ 1 (" + fixed6(o.p.ep) + ")");
    }
  }
  o.sinip = std::sin(o.p.inclp);
  o.cosip = std::cos(o.p.inclp);
  if (m.deep) {
    const auto& g = wgs72();
    constexpr double kTemp4 = 1.5e-12;
    o.aycof = -0.5 * g.j3oj2 * o.sinip;
    const double divisor = std::fabs(o.cosip + 1.0) > kTemp4 ? 1.0 + o.cosip : kTemp4;
    o.xlcof = -0.25 * g.j3oj2 * o.sinip * (3.0 + 5.0 * o.cosip) / divisor;
    const double cosisq = o.cosip * o.cosip;
    o.con41 = 3.0 * cosisq - 1.0;
    o.x1mth2 = 1.0 - cosisq;
    o.x7thm1 = 7.0 * cosisq - 1.0;
  }
  return o;
}

/// Kepler's equation for the eccentric longitude, in the reference's form: Newton steps capped
/// at 0.95 rad, at most 10, until the step is below 1e-12. The sine and cosine returned are
/// those of the last iterate the step was computed from, as the reference uses them.
struct Kepler {
  double sineo1, coseo1;
};

Kepler solve_kepler(double u, double axnl, double aynl) {
  double eo1 = u;
  double tem5 = 9999.9;
  Kepler k{};
  for (int ktr = 1; std::fabs(tem5) >= 1.0e-12 && ktr <= 10; ++ktr) {
    k.sineo1 = std::sin(eo1);
    k.coseo1 = std::cos(eo1);
    tem5 = 1.0 - k.coseo1 * axnl - k.sineo1 * aynl;
    tem5 = (u - aynl * k.coseo1 + axnl * k.sineo1 - eo1) / tem5;
    if (std::fabs(tem5) >= 0.95) tem5 = tem5 > 0.0 ? 0.95 : -0.95;
    eo1 = eo1 + tem5;
  }
  return k;
}

/// Long-period terms, Kepler, short-period terms and the TEME vectors.
Result<TemeState> position_velocity(const Osculating& o, double am, double nm) {
  const auto& g = wgs72();
  const Perturbed& p = o.p;
  const double axnl = p.ep * std::cos(p.argpp);
  double temp = 1.0 / (am * (1.0 - p.ep * p.ep));
  const double aynl = p.ep * std::sin(p.argpp) + temp * o.aycof;
  const double xl = p.mp + p.argpp + p.nodep + temp * o.xlcof * axnl;
  const double u = std::fmod(xl - p.nodep, kTwoPi);
  const Kepler k = solve_kepler(u, axnl, aynl);
  const double ecose = axnl * k.coseo1 + aynl * k.sineo1;
  const double esine = axnl * k.sineo1 - aynl * k.coseo1;
  const double el2 = axnl * axnl + aynl * aynl;
  const double pl = am * (1.0 - el2);
  if (pl < 0.0) return fail("semi-latus rectum below zero (" + fixed6(pl) + ")");
  const double rl = am * (1.0 - ecose);
  const double rdotl = std::sqrt(am) * esine / rl;
  const double rvdotl = std::sqrt(pl) / rl;
  const double betal = std::sqrt(1.0 - el2);
  temp = esine / (1.0 + betal);
  const double sinu = am / rl * (k.sineo1 - aynl - axnl * temp);
  const double cosu = am / rl * (k.coseo1 - axnl + aynl * temp);
  double su = std::atan2(sinu, cosu);
  const double sin2u = (cosu + cosu) * sinu;
  const double cos2u = 1.0 - 2.0 * sinu * sinu;
  temp = 1.0 / pl;
  const double temp1 = 0.5 * g.j2 * temp;
  const double temp2 = temp1 * temp;
  const double mrt = rl * (1.0 - 1.5 * temp2 * betal * o.con41) + 0.5 * temp1 * o.x1mth2 * cos2u;
  su = su - 0.25 * temp2 * o.x7thm1 * sin2u;
  const double xnode = p.nodep + 1.5 * temp2 * o.cosip * sin2u;
  const double xinc = p.inclp + 1.5 * temp2 * o.cosip * o.sinip * cos2u;
  const double mvt = rdotl - nm * temp1 * o.x1mth2 * sin2u / g.xke;
  const double rvdot = rvdotl + nm * temp1 * (o.x1mth2 * cos2u + 1.5 * o.con41) / g.xke;
  if (mrt < 1.0) {
    return fail("decayed: the orbit is below the Earth's surface (radius " + fixed6(mrt) +
                " Earth radii)");
  }
  // Unit vectors along the radius (u) and across it in the orbit plane (v).
  const double sinsu = std::sin(su);
  const double cossu = std::cos(su);
  const double snod = std::sin(xnode);
  const double cnod = std::cos(xnode);
  const double sini = std::sin(xinc);
  const double cosi = std::cos(xinc);
  const double xmx = -snod * cosi;
  const double xmy = cnod * cosi;
  const std::array<double, 3> ur = {xmx * sinsu + cnod * cossu, xmy * sinsu + snod * cossu,
                                    sini * sinsu};
  const std::array<double, 3> vr = {xmx * cossu - cnod * sinsu, xmy * cossu - snod * sinsu,
                                    sini * cossu};
  const double vkmpersec = g.radius_km * g.xke / 60.0;
  const double mr = mrt * g.radius_km;
  TemeState state;
  for (std::size_t i = 0; i < 3; ++i) {
    state.r_km.at(i) = mr * ur.at(i);
    state.v_km_s.at(i) = (mvt * ur.at(i) + rvdot * vr.at(i)) * vkmpersec;
  }
  return state;
}

}  // namespace

Result<TemeState> Sgp4::at_minutes(double t) const {
  const auto with_label = [&](const Error& e) {
    return fail(elements_.label() + ": " + e.message);
  };
  if (!std::isfinite(t)) return fail(elements_.label() + ": time is not a finite number");
  Secular s = secular_terms(model_, t);
  if (model_.deep) s.mean = sgp4_detail::deep_space_secular(model_, t, s.mean);
  const Result<MeanElements> mean = apply_drag(model_, s);
  if (!mean) return with_label(mean.error());
  const Result<Osculating> osc = periodics(model_, *mean, t);
  if (!osc) return with_label(osc.error());
  Result<TemeState> state = position_velocity(*osc, mean->am, mean->nm);
  if (!state) return with_label(state.error());
  return state;
}

Result<TemeState> Sgp4::at_jd(double jd_whole, double jd_frac) const {
  constexpr double kMinutesPerDay = 1440.0;
  // Whole and fraction apart, as the reference does, so that no 2.4e6-day sum loses digits.
  const double t = (jd_whole - elements_.epoch_jd) * kMinutesPerDay +
                   (jd_frac - elements_.epoch_jd_frac) * kMinutesPerDay;
  return at_minutes(t);
}

}  // namespace azt::orbit
