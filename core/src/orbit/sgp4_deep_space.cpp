// SDP4, the deep-space part of SGP4 (Vallado et al. 2006: dscom, dsinit, dspace, dpper; from
// Hujsak's 1979 deep-space model in Spacetrack Report #3). Orbits with periods of 225 min or more
// feel the Sun and the Moon (long-period and secular terms) and, near 12 h or 24 h periods, the
// tesseral resonances of the geopotential, which are integrated numerically in 720-min steps.
// The numeric constants are the paper's; operand order follows it for bit-level agreement.

#include <array>
#include <cmath>
#include <numbers>

#include "sgp4_internal.hpp"

namespace azt::orbit::sgp4_detail {

namespace {

using Resonance = Sgp4DeepSpace::Resonance;
constexpr double kPi = std::numbers::pi;

// Solar and lunar mean motions (rad/min) and orbit eccentricities.
constexpr double kZns = 1.19459e-5;
constexpr double kZes = 0.01675;
constexpr double kZnl = 1.5835218e-4;
constexpr double kZel = 0.05490;
// Earth's rotation rate, rad/min (7.29211514668855e-5 rad/s).
constexpr double kRptim = 4.37526908801129966e-3;
// Below 3° (and above 177°) of inclination the node terms are dropped (dsinit).
constexpr double kLowInclination = 5.2359877e-2;

/// The orientation of the perturbing body's orbit relative to the satellite's (dscom's loop
/// over the Sun, then the Moon).
struct BodyGeometry {
  double zcosg, zsing, zcosi, zsini, zcosh, zsinh, cc;
};

/// The satellite orbit quantities dscom's per-body terms use.
struct OrbitAngles {
  double em, emsq, betasq, rtemsq, sinim, cosim, sinomm, cosomm, xnoi;
};

/// dscom's s1…s7 and z1…z33 for one body.
struct BodyTerms {
  double s1, s2, s3, s4, s5, s6, s7;
  double z1, z2, z3, z11, z12, z13, z21, z22, z23, z31, z32, z33;
};

BodyTerms body_terms(const BodyGeometry& b, const OrbitAngles& o) {
  const double a1 = b.zcosg * b.zcosh + b.zsing * b.zcosi * b.zsinh;
  const double a3 = -b.zsing * b.zcosh + b.zcosg * b.zcosi * b.zsinh;
  const double a7 = -b.zcosg * b.zsinh + b.zsing * b.zcosi * b.zcosh;
  const double a8 = b.zsing * b.zsini;
  const double a9 = b.zsing * b.zsinh + b.zcosg * b.zcosi * b.zcosh;
  const double a10 = b.zcosg * b.zsini;
  const double a2 = o.cosim * a7 + o.sinim * a8;
  const double a4 = o.cosim * a9 + o.sinim * a10;
  const double a5 = -o.sinim * a7 + o.cosim * a8;
  const double a6 = -o.sinim * a9 + o.cosim * a10;
  const double x1 = a1 * o.cosomm + a2 * o.sinomm;
  const double x2 = a3 * o.cosomm + a4 * o.sinomm;
  const double x3 = -a1 * o.sinomm + a2 * o.cosomm;
  const double x4 = -a3 * o.sinomm + a4 * o.cosomm;
  const double x5 = a5 * o.sinomm;
  const double x6 = a6 * o.sinomm;
  const double x7 = a5 * o.cosomm;
  const double x8 = a6 * o.cosomm;
  BodyTerms t{};
  t.z31 = 12.0 * x1 * x1 - 3.0 * x3 * x3;
  t.z32 = 24.0 * x1 * x2 - 6.0 * x3 * x4;
  t.z33 = 12.0 * x2 * x2 - 3.0 * x4 * x4;
  t.z1 = 3.0 * (a1 * a1 + a2 * a2) + t.z31 * o.emsq;
  t.z2 = 6.0 * (a1 * a3 + a2 * a4) + t.z32 * o.emsq;
  t.z3 = 3.0 * (a3 * a3 + a4 * a4) + t.z33 * o.emsq;
  t.z11 = -6.0 * a1 * a5 + o.emsq * (-24.0 * x1 * x7 - 6.0 * x3 * x5);
  t.z12 = -6.0 * (a1 * a6 + a3 * a5) +
          o.emsq * (-24.0 * (x2 * x7 + x1 * x8) - 6.0 * (x3 * x6 + x4 * x5));
  t.z13 = -6.0 * a3 * a6 + o.emsq * (-24.0 * x2 * x8 - 6.0 * x4 * x6);
  t.z21 = 6.0 * a2 * a5 + o.emsq * (24.0 * x1 * x5 - 6.0 * x3 * x7);
  t.z22 =
      6.0 * (a4 * a5 + a2 * a6) + o.emsq * (24.0 * (x2 * x5 + x1 * x6) - 6.0 * (x4 * x7 + x3 * x8));
  t.z23 = 6.0 * a4 * a6 + o.emsq * (24.0 * x2 * x6 - 6.0 * x4 * x8);
  t.z1 = t.z1 + t.z1 + o.betasq * t.z31;
  t.z2 = t.z2 + t.z2 + o.betasq * t.z32;
  t.z3 = t.z3 + t.z3 + o.betasq * t.z33;
  t.s3 = b.cc * o.xnoi;
  t.s2 = -0.5 * t.s3 / o.rtemsq;
  t.s4 = t.s3 * o.rtemsq;
  t.s1 = -15.0 * o.em * t.s4;
  t.s5 = x1 * x3 + x2 * x4;
  t.s6 = x2 * x3 + x1 * x4;
  t.s7 = x2 * x4 - x1 * x3;
  return t;
}

/// dscom: the Sun's and the Moon's terms at epoch (`sun` = the paper's ss*, sz*; `moon` = s*,
/// z*) and the long-period coefficients dpper uses.
struct Dscom {
  OrbitAngles o;
  BodyTerms sun, moon;
};

Dscom dscom(const Sgp4Model& m, Sgp4DeepSpace& ds) {
  constexpr double kC1ss = 2.9864797e-6;
  constexpr double kC1l = 4.7968065e-7;
  constexpr double kZsinis = 0.39785416;  // sine and cosine of the obliquity
  constexpr double kZcosis = 0.91744867;
  constexpr double kZcosgs = 0.1945905;  // of the Sun's argument of perigee
  constexpr double kZsings = -0.98088458;
  Dscom d{};
  OrbitAngles& o = d.o;
  o.em = m.ecco;
  o.emsq = o.em * o.em;
  o.betasq = 1.0 - o.emsq;
  o.rtemsq = std::sqrt(o.betasq);
  o.sinim = std::sin(m.inclo);
  o.cosim = std::cos(m.inclo);
  o.sinomm = std::sin(m.argpo);
  o.cosomm = std::cos(m.argpo);
  o.xnoi = 1.0 / m.no_unkozai;
  const double snodm = std::sin(m.nodeo);
  const double cnodm = std::cos(m.nodeo);
  // Days since 1900 Jan 0.5 (tc = 0 at initialisation): the lunar node and perigee.
  const double day = m.epoch_days_1950 + 18261.5;
  const double xnodce = std::fmod(4.5236020 - 9.2422029e-4 * day, kTwoPi);
  const double stem = std::sin(xnodce);
  const double ctem = std::cos(xnodce);
  const double zcosil = 0.91375164 - 0.03568096 * ctem;
  const double zsinil = std::sqrt(1.0 - zcosil * zcosil);
  const double zsinhl = 0.089683511 * stem / zsinil;
  const double zcoshl = std::sqrt(1.0 - zsinhl * zsinhl);
  const double gam = 5.8351514 + 0.0019443680 * day;
  double zx = 0.39785416 * stem / zsinil;
  const double zy = zcoshl * ctem + 0.91744867 * zsinhl * stem;
  zx = std::atan2(zx, zy);
  zx = gam + zx - xnodce;
  d.sun = body_terms({kZcosgs, kZsings, kZcosis, kZsinis, cnodm, snodm, kC1ss}, o);
  d.moon = body_terms({std::cos(zx), std::sin(zx), zcosil, zsinil, zcoshl * cnodm + zsinhl * snodm,
                       snodm * zcoshl - cnodm * zsinhl, kC1l},
                      o);
  ds.zmol = std::fmod(4.7199672 + 0.22997150 * day - gam, kTwoPi);
  ds.zmos = std::fmod(6.2565837 + 0.017201977 * day, kTwoPi);
  return d;
}

/// dscom's last step: the long-period periodic coefficients of both bodies.
void periodic_coefficients(const Dscom& d, Sgp4DeepSpace& ds) {
  const BodyTerms& s = d.sun;
  const BodyTerms& l = d.moon;
  const double emsq = d.o.emsq;
  ds.se2 = 2.0 * s.s1 * s.s6;
  ds.se3 = 2.0 * s.s1 * s.s7;
  ds.si2 = 2.0 * s.s2 * s.z12;
  ds.si3 = 2.0 * s.s2 * (s.z13 - s.z11);
  ds.sl2 = -2.0 * s.s3 * s.z2;
  ds.sl3 = -2.0 * s.s3 * (s.z3 - s.z1);
  ds.sl4 = -2.0 * s.s3 * (-21.0 - 9.0 * emsq) * kZes;
  ds.sgh2 = 2.0 * s.s4 * s.z32;
  ds.sgh3 = 2.0 * s.s4 * (s.z33 - s.z31);
  ds.sgh4 = -18.0 * s.s4 * kZes;
  ds.sh2 = -2.0 * s.s2 * s.z22;
  ds.sh3 = -2.0 * s.s2 * (s.z23 - s.z21);
  ds.ee2 = 2.0 * l.s1 * l.s6;
  ds.e3 = 2.0 * l.s1 * l.s7;
  ds.xi2 = 2.0 * l.s2 * l.z12;
  ds.xi3 = 2.0 * l.s2 * (l.z13 - l.z11);
  ds.xl2 = -2.0 * l.s3 * l.z2;
  ds.xl3 = -2.0 * l.s3 * (l.z3 - l.z1);
  ds.xl4 = -2.0 * l.s3 * (-21.0 - 9.0 * emsq) * kZel;
  ds.xgh2 = 2.0 * l.s4 * l.z32;
  ds.xgh3 = 2.0 * l.s4 * (l.z33 - l.z31);
  ds.xgh4 = -18.0 * l.s4 * kZel;
  ds.xh2 = -2.0 * l.s2 * l.z22;
  ds.xh3 = -2.0 * l.s2 * (l.z23 - l.z21);
}

/// dsinit, first half: the lunar-solar secular rates of e, i, ω, Ω and M.
void secular_rates(const Dscom& d, double inclm, Sgp4DeepSpace& ds) {
  const BodyTerms& s = d.sun;
  const BodyTerms& l = d.moon;
  const OrbitAngles& o = d.o;
  const bool near_equatorial = inclm < kLowInclination || inclm > kPi - kLowInclination;
  const double ses = s.s1 * kZns * s.s5;
  const double sis = s.s2 * kZns * (s.z11 + s.z13);
  const double sls = -kZns * s.s3 * (s.z1 + s.z3 - 14.0 - 6.0 * o.emsq);
  const double sghs = s.s4 * kZns * (s.z31 + s.z33 - 6.0);
  double shs = -kZns * s.s2 * (s.z21 + s.z23);
  if (near_equatorial) shs = 0.0;
  if (o.sinim != 0.0) shs = shs / o.sinim;
  const double sgs = sghs - o.cosim * shs;
  ds.dedt = ses + l.s1 * kZnl * l.s5;
  ds.didt = sis + l.s2 * kZnl * (l.z11 + l.z13);
  ds.dmdt = sls - kZnl * l.s3 * (l.z1 + l.z3 - 14.0 - 6.0 * o.emsq);
  const double sghl = l.s4 * kZnl * (l.z31 + l.z33 - 6.0);
  double shll = -kZnl * l.s2 * (l.z21 + l.z23);
  if (near_equatorial) shll = 0.0;
  ds.domdt = sgs + sghl;
  ds.dnodt = shs;
  if (o.sinim != 0.0) {
    ds.domdt = ds.domdt - o.cosim / o.sinim * shll;
    ds.dnodt = ds.dnodt + shll / o.sinim;
  }
}

/// The G functions of eccentricity for the 12-hour resonance (dsinit's polynomial fits).
struct HalfDayG {
  double g201, g211, g310, g322, g410, g422, g520, g521, g532, g533;
};

HalfDayG half_day_g(double em) {
  const double emsq = em * em;
  const double eoc = em * emsq;
  HalfDayG g{};
  g.g201 = -0.306 - (em - 0.64) * 0.440;
  if (em <= 0.65) {
    g.g211 = 3.616 - 13.2470 * em + 16.2900 * emsq;
    g.g310 = -19.302 + 117.3900 * em - 228.4190 * emsq + 156.5910 * eoc;
    g.g322 = -18.9068 + 109.7927 * em - 214.6334 * emsq + 146.5816 * eoc;
    g.g410 = -41.122 + 242.6940 * em - 471.0940 * emsq + 313.9530 * eoc;
    g.g422 = -146.407 + 841.8800 * em - 1629.014 * emsq + 1083.4350 * eoc;
    g.g520 = -532.114 + 3017.977 * em - 5740.032 * emsq + 3708.2760 * eoc;
  } else {
    g.g211 = -72.099 + 331.819 * em - 508.738 * emsq + 266.724 * eoc;
    g.g310 = -346.844 + 1582.851 * em - 2415.925 * emsq + 1246.113 * eoc;
    g.g322 = -342.585 + 1554.908 * em - 2366.899 * emsq + 1215.972 * eoc;
    g.g410 = -1052.797 + 4758.686 * em - 7193.992 * emsq + 3651.957 * eoc;
    g.g422 = -3581.690 + 16178.110 * em - 24462.770 * emsq + 12422.520 * eoc;
    if (em > 0.715) {
      g.g520 = -5149.66 + 29936.92 * em - 54087.36 * emsq + 31324.56 * eoc;
    } else {
      g.g520 = 1464.74 - 4664.75 * em + 3763.64 * emsq;
    }
  }
  if (em < 0.7) {
    g.g533 = -919.22770 + 4988.6100 * em - 9064.7700 * emsq + 5542.21 * eoc;
    g.g521 = -822.71072 + 4568.6173 * em - 8491.4146 * emsq + 5337.524 * eoc;
    g.g532 = -853.66600 + 4690.2500 * em - 8624.7700 * emsq + 5341.4 * eoc;
  } else {
    g.g533 = -37995.780 + 161616.52 * em - 229838.20 * emsq + 109377.94 * eoc;
    g.g521 = -51752.104 + 218913.95 * em - 309468.16 * emsq + 146349.42 * eoc;
    g.g532 = -40023.880 + 170470.89 * em - 242699.48 * emsq + 115605.82 * eoc;
  }
  return g;
}

/// dsinit for the 12-hour (Molniya) resonance: the d-coefficients of the 2-2, 3-2, 4-4 and
/// 5-2/5-4 tesseral harmonics.
void init_half_day(const Sgp4Model& m, const OrbitAngles& o, double aonv, double theta,
                   Sgp4DeepSpace& ds) {
  constexpr double kRoot22 = 1.7891679e-6;
  constexpr double kRoot32 = 3.7393792e-7;
  constexpr double kRoot44 = 7.3636953e-9;
  constexpr double kRoot52 = 1.1428639e-7;
  constexpr double kRoot54 = 2.1765803e-9;
  const double sinim = o.sinim;
  const double cosim = o.cosim;
  const double cosisq = cosim * cosim;
  const HalfDayG g = half_day_g(m.ecco);
  const double sini2 = sinim * sinim;
  const double f220 = 0.75 * (1.0 + 2.0 * cosim + cosisq);
  const double f221 = 1.5 * sini2;
  const double f321 = 1.875 * sinim * (1.0 - 2.0 * cosim - 3.0 * cosisq);
  const double f322 = -1.875 * sinim * (1.0 + 2.0 * cosim - 3.0 * cosisq);
  const double f441 = 35.0 * sini2 * f220;
  const double f442 = 39.3750 * sini2 * sini2;
  const double f522 = 9.84375 * sinim *
                      (sini2 * (1.0 - 2.0 * cosim - 5.0 * cosisq) +
                       0.33333333 * (-2.0 + 4.0 * cosim + 6.0 * cosisq));
  const double f523 = sinim * (4.92187512 * sini2 * (-2.0 - 4.0 * cosim + 10.0 * cosisq) +
                               6.56250012 * (1.0 + 2.0 * cosim - 3.0 * cosisq));
  const double f542 =
      29.53125 * sinim * (2.0 - 8.0 * cosim + cosisq * (-12.0 + 8.0 * cosim + 10.0 * cosisq));
  const double f543 =
      29.53125 * sinim * (-2.0 - 8.0 * cosim + cosisq * (12.0 + 8.0 * cosim - 10.0 * cosisq));
  const double nm = m.no_unkozai;
  const double xno2 = nm * nm;
  const double ainv2 = aonv * aonv;
  double temp1 = 3.0 * xno2 * ainv2;
  double temp = temp1 * kRoot22;
  ds.d2201 = temp * f220 * g.g201;
  ds.d2211 = temp * f221 * g.g211;
  temp1 = temp1 * aonv;
  temp = temp1 * kRoot32;
  ds.d3210 = temp * f321 * g.g310;
  ds.d3222 = temp * f322 * g.g322;
  temp1 = temp1 * aonv;
  temp = 2.0 * temp1 * kRoot44;
  ds.d4410 = temp * f441 * g.g410;
  ds.d4422 = temp * f442 * g.g422;
  temp1 = temp1 * aonv;
  temp = temp1 * kRoot52;
  ds.d5220 = temp * f522 * g.g520;
  ds.d5232 = temp * f523 * g.g532;
  temp = 2.0 * temp1 * kRoot54;
  ds.d5421 = temp * f542 * g.g521;
  ds.d5433 = temp * f543 * g.g533;
  ds.xlamo = std::fmod(m.mo + m.nodeo + m.nodeo - theta - theta, kTwoPi);
  ds.xfact = m.mdot + ds.dmdt + 2.0 * (m.nodedot + ds.dnodt - kRptim) - m.no_unkozai;
}

/// dsinit for the 24-hour (geosynchronous) resonance: the 2-2-0-0, 3-1-1-0 and 3-3-0-0 terms.
void init_one_day(const Sgp4Model& m, const OrbitAngles& o, double aonv, double theta,
                  Sgp4DeepSpace& ds) {
  constexpr double kQ22 = 1.7891679e-6;
  constexpr double kQ31 = 2.1460748e-6;
  constexpr double kQ33 = 2.2123015e-7;
  const double emsq = o.emsq;
  const double cosim = o.cosim;
  const double sinim = o.sinim;
  const double nm = m.no_unkozai;
  const double g200 = 1.0 + emsq * (-2.5 + 0.8125 * emsq);
  const double g310 = 1.0 + 2.0 * emsq;
  const double g300 = 1.0 + emsq * (-6.0 + 6.60937 * emsq);
  const double f220 = 0.75 * (1.0 + cosim) * (1.0 + cosim);
  const double f311 = 0.9375 * sinim * sinim * (1.0 + 3.0 * cosim) - 0.75 * (1.0 + cosim);
  double f330 = 1.0 + cosim;
  f330 = 1.875 * f330 * f330 * f330;
  double del1 = 3.0 * nm * nm * aonv * aonv;
  ds.del2 = 2.0 * del1 * f220 * g200 * kQ22;
  ds.del3 = 3.0 * del1 * f330 * g300 * kQ33 * aonv;
  ds.del1 = del1 * f311 * g310 * kQ31 * aonv;
  ds.xlamo = std::fmod(m.mo + m.nodeo + m.argpo - theta, kTwoPi);
  const double xpidot = m.argpdot + m.nodedot;
  ds.xfact = m.mdot + xpidot - kRptim + ds.dmdt + ds.domdt + ds.dnodt - m.no_unkozai;
}

}  // namespace

void init_deep_space(Sgp4Model& m) {
  Sgp4DeepSpace& ds = m.ds;
  const Dscom d = dscom(m, ds);
  periodic_coefficients(d, ds);
  // The reference calls dpper here in its initialisation mode, which changes nothing in the
  // 2006 code (the epoch offsets peo … pho stay zero), so it is left out.
  secular_rates(d, m.inclo, ds);
  const double nm = m.no_unkozai;
  if (nm > 0.0034906585 && nm < 0.0052359877) ds.resonance = Resonance::OneDay;
  if (nm >= 8.26e-3 && nm <= 9.24e-3 && m.ecco >= 0.5) ds.resonance = Resonance::HalfDay;
  if (ds.resonance == Resonance::None) return;
  const double theta = std::fmod(m.gsto, kTwoPi);
  const double aonv = std::pow(nm / wgs72().xke, kTwoThirds);
  if (ds.resonance == Resonance::HalfDay) {
    init_half_day(m, d.o, aonv, theta, ds);
  } else {
    init_one_day(m, d.o, aonv, theta, ds);
  }
}

namespace {

/// The resonance integrator's derivatives at the current state (dspace).
struct ResonanceRates {
  double xndt, xldot, xnddt;
};

ResonanceRates resonance_rates(const Sgp4Model& m, double xli, double xni, double atime) {
  const Sgp4DeepSpace& ds = m.ds;
  ResonanceRates r{};
  r.xldot = xni + ds.xfact;
  if (ds.resonance == Resonance::OneDay) {
    constexpr double kFasx2 = 0.13130908;
    constexpr double kFasx4 = 2.8843198;
    constexpr double kFasx6 = 0.37448087;
    r.xndt = ds.del1 * std::sin(xli - kFasx2) + ds.del2 * std::sin(2.0 * (xli - kFasx4)) +
             ds.del3 * std::sin(3.0 * (xli - kFasx6));
    r.xnddt = ds.del1 * std::cos(xli - kFasx2) + 2.0 * ds.del2 * std::cos(2.0 * (xli - kFasx4)) +
              3.0 * ds.del3 * std::cos(3.0 * (xli - kFasx6));
  } else {
    constexpr double kG22 = 5.7686396;
    constexpr double kG32 = 0.95240898;
    constexpr double kG44 = 1.8014998;
    constexpr double kG52 = 1.0508330;
    constexpr double kG54 = 4.4108898;
    const double xomi = m.argpo + m.argpdot * atime;
    const double x2omi = xomi + xomi;
    const double x2li = xli + xli;
    r.xndt = (ds.d2201 * std::sin(x2omi + xli - kG22) + ds.d2211 * std::sin(xli - kG22) +
              ds.d3210 * std::sin(xomi + xli - kG32) + ds.d3222 * std::sin(-xomi + xli - kG32) +
              ds.d4410 * std::sin(x2omi + x2li - kG44) + ds.d4422 * std::sin(x2li - kG44) +
              ds.d5220 * std::sin(xomi + xli - kG52) + ds.d5232 * std::sin(-xomi + xli - kG52) +
              ds.d5421 * std::sin(xomi + x2li - kG54) + ds.d5433 * std::sin(-xomi + x2li - kG54));
    r.xnddt = (ds.d2201 * std::cos(x2omi + xli - kG22) + ds.d2211 * std::cos(xli - kG22) +
               ds.d3210 * std::cos(xomi + xli - kG32) + ds.d3222 * std::cos(-xomi + xli - kG32) +
               ds.d5220 * std::cos(xomi + xli - kG52) + ds.d5232 * std::cos(-xomi + xli - kG52) +
               2.0 * (ds.d4410 * std::cos(x2omi + x2li - kG44) + ds.d4422 * std::cos(x2li - kG44) +
                      ds.d5421 * std::cos(xomi + x2li - kG54) +
                      ds.d5433 * std::cos(-xomi + x2li - kG54)));
  }
  r.xnddt = r.xnddt * r.xldot;
  return r;
}

}  // namespace

DeepMean deep_space_secular(const Sgp4Model& m, double t, const DeepMean& in) {
  const Sgp4DeepSpace& ds = m.ds;
  DeepMean out = in;
  out.em = in.em + ds.dedt * t;
  out.inclm = in.inclm + ds.didt * t;
  out.argpm = in.argpm + ds.domdt * t;
  out.nodem = in.nodem + ds.dnodt * t;
  out.mm = in.mm + ds.dmdt * t;
  if (ds.resonance == Resonance::None) return out;
  // Euler-Maclaurin steps of 720 min from epoch towards t, then a Taylor step for the rest.
  constexpr double kStep = 720.0;
  constexpr double kStep2 = 259200.0;  // kStep² / 2
  const double delt = t > 0.0 ? kStep : -kStep;
  double atime = 0.0;
  double xli = ds.xlamo;
  double xni = m.no_unkozai;
  ResonanceRates r = resonance_rates(m, xli, xni, atime);
  while (std::fabs(t - atime) >= kStep) {
    xli = xli + r.xldot * delt + r.xndt * kStep2;
    xni = xni + r.xndt * delt + r.xnddt * kStep2;
    atime = atime + delt;
    r = resonance_rates(m, xli, xni, atime);
  }
  const double ft = t - atime;
  const double nm = xni + r.xndt * ft + r.xnddt * ft * ft * 0.5;
  const double xl = xli + r.xldot * ft + r.xndt * ft * ft * 0.5;
  const double theta = std::fmod(m.gsto + t * kRptim, kTwoPi);
  if (ds.resonance == Resonance::OneDay) {
    out.mm = xl - out.nodem - out.argpm + theta;
  } else {
    out.mm = xl - 2.0 * out.nodem + 2.0 * theta;
  }
  const double dndt = nm - m.no_unkozai;
  out.nm = m.no_unkozai + dndt;
  return out;
}

namespace {

/// dpper's per-body long-period sums at time t: (e, i, l, g, h) from one body's coefficients.
struct BodyPeriodics {
  double pe, pinc, pl, pgh, ph;
};

BodyPeriodics body_periodics(double zm, double ze, const std::array<double, 12>& c) {
  const double zf = zm + 2.0 * ze * std::sin(zm);
  const double sinzf = std::sin(zf);
  const double f2 = 0.5 * sinzf * sinzf - 0.25;
  const double f3 = -0.5 * sinzf * std::cos(zf);
  // c: e2 e3 i2 i3 l2 l3 l4 gh2 gh3 gh4 h2 h3
  return BodyPeriodics{c[0] * f2 + c[1] * f3, c[2] * f2 + c[3] * f3,
                       c[4] * f2 + c[5] * f3 + c[6] * sinzf, c[7] * f2 + c[8] * f3 + c[9] * sinzf,
                       c[10] * f2 + c[11] * f3};
}

}  // namespace

Perturbed deep_space_periodics(const Sgp4Model& m, double t, const Perturbed& in) {
  const Sgp4DeepSpace& ds = m.ds;
  const BodyPeriodics sun = body_periodics(ds.zmos + kZns * t, kZes,
                                           {ds.se2, ds.se3, ds.si2, ds.si3, ds.sl2, ds.sl3, ds.sl4,
                                            ds.sgh2, ds.sgh3, ds.sgh4, ds.sh2, ds.sh3});
  const BodyPeriodics moon = body_periodics(ds.zmol + kZnl * t, kZel,
                                            {ds.ee2, ds.e3, ds.xi2, ds.xi3, ds.xl2, ds.xl3, ds.xl4,
                                             ds.xgh2, ds.xgh3, ds.xgh4, ds.xh2, ds.xh3});
  const double pe = sun.pe + moon.pe;
  const double pinc = sun.pinc + moon.pinc;
  const double pl = sun.pl + moon.pl;
  double pgh = sun.pgh + moon.pgh;
  double ph = sun.ph + moon.ph;
  Perturbed p = in;
  p.inclp = in.inclp + pinc;
  p.ep = in.ep + pe;
  const double sinip = std::sin(p.inclp);
  const double cosip = std::cos(p.inclp);
  if (p.inclp >= 0.2) {
    ph = ph / sinip;
    pgh = pgh - cosip * ph;
    p.argpp = p.argpp + pgh;
    p.nodep = p.nodep + ph;
    p.mp = p.mp + pl;
    return p;
  }
  // Lyddane's modification for low inclinations: perturb the node through the components of
  // sin(i)·(sin Ω, cos Ω), which stay regular as i → 0 (the GSFC choice of testing the perturbed
  // inclination, as the 2006 paper does).
  const double sinop = std::sin(p.nodep);
  const double cosop = std::cos(p.nodep);
  double alfdp = sinip * sinop;
  double betdp = sinip * cosop;
  const double dalf = ph * cosop + pinc * cosip * sinop;
  const double dbet = -ph * sinop + pinc * cosip * cosop;
  alfdp = alfdp + dalf;
  betdp = betdp + dbet;
  p.nodep = std::fmod(p.nodep, kTwoPi);
  const double xls = p.mp + p.argpp + pl + pgh + (cosip - pinc * sinip) * p.nodep;
  const double xnoh = p.nodep;
  p.nodep = std::atan2(alfdp, betdp);
  if (std::fabs(xnoh - p.nodep) > kPi) p.nodep += (p.nodep < xnoh) ? kTwoPi : -kTwoPi;
  p.mp = p.mp + pl;
  p.argpp = xls - p.mp - cosip * p.nodep;
  return p;
}

}  // namespace azt::orbit::sgp4_detail
