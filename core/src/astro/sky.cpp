// Apparent topocentric places: one reduction shared by every ephemeris backend.
//
// Chain (IERS Conventions 2010 ch. 5, CIO-based, as ERFA's eraApco/eraAtciq/eraAtioq):
//   geometric BCRS states from the Ephemeris → light time in the barycentric frame →
//   annual + diurnal aberration (observer barycentric velocity) → GCRS→CIRS (IAU 2000B) →
//   Earth rotation angle of UT1 → observed azimuth / airless elevation.
// Range is the one-way light-time distance |X(t−τ) − O(t)| in the barycentric frame, which is what
// Swiss Ephemeris reports; range rate is its exact derivative (see range_rate()).
#include "azt/astro/sky.hpp"

#include <erfa.h>
#include <erfam.h>

#include <cmath>

namespace azt::astro {
namespace {

constexpr double kSpeedOfLightAuPerDay = ERFA_CMPS * ERFA_DAYSEC / ERFA_DAU;
constexpr double kKmPerAu = ERFA_DAU / 1000.0;
constexpr double kSpeedOfLightKmS = ERFA_CMPS / 1000.0;
// GM of the Sun in au³/day²: the Gaussian gravitational constant k = 0.01720209895 squared
// (IAU 1976; consistent with the IAU 2012 au to 1e-10).
constexpr double kGaussK = 0.01720209895;
constexpr double kGmSun = kGaussK * kGaussK;
// Sun / (Earth + Moon) mass ratio, JPL DE430 (Folkner et al. 2014, table 8).
constexpr double kSunOverEarthMoon = 328900.5596;
constexpr double kGmEarthMoon = kGmSun / kSunOverEarthMoon;
// Three light-time iterations converge to < 1 µm for the Moon and < 1 mm for the Sun.
constexpr int kLightTimeIterations = 3;

Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 scale(const Vec3& a, double k) { return {a[0] * k, a[1] * k, a[2] * k}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

/// Two-body acceleration towards a centre (au/day²) of a body at `r` (au) from it.
Vec3 kepler_acceleration(const Vec3& r, double gm) {
  const double d = norm(r);
  return scale(r, -gm / (d * d * d));
}

/// State at t − τ from the state at t, to second order: the residual (third-order) term is
/// < 1e-6 m for the Moon (τ ≈ 1.3 s) and < 1 mm for the Sun's barycentric motion (τ ≈ 499 s).
PosVel extrapolate_back(const PosVel& at_t, const Vec3& accel, double tau_d) {
  PosVel out;
  out.pos_au =
      add(sub(at_t.pos_au, scale(at_t.vel_au_d, tau_d)), scale(accel, 0.5 * tau_d * tau_d));
  out.vel_au_d = sub(at_t.vel_au_d, scale(accel, tau_d));
  return out;
}

eraASTROM to_astrom(const Station& st) {
  eraASTROM a{};
  a.pmt = st.pmt;
  for (int i = 0; i < 3; ++i) {
    a.eb[i] = st.eb[i];
    a.eh[i] = st.eh[i];
    a.v[i] = st.v[i];
    for (int j = 0; j < 3; ++j) a.bpn[i][j] = st.bpn[i][j];
  }
  a.em = st.em;
  a.bm1 = st.bm1;
  a.along = st.along;
  a.phi = st.phi;
  a.xpl = st.xpl;
  a.ypl = st.ypl;
  a.sphi = st.sphi;
  a.cphi = st.cphi;
  a.diurab = st.diurab;
  a.eral = st.eral;
  a.refa = 0.0;  // refraction is applied afterwards by refraction.cpp
  a.refb = 0.0;
  return a;
}

Vec3 observer_velocity_au_d(const Station& st) {
  return scale(Vec3{st.v[0], st.v[1], st.v[2]}, kSpeedOfLightAuPerDay);
}

/// From a CIRS direction to the observed, airless place.
// ERFA's C API takes non-const pointers it does not write through: pass a local copy.
Place place_from_cirs(const Epoch& epoch, eraASTROM astrom, double ri, double di) {
  double aob = 0, zob = 0, hob = 0, dob = 0, rob = 0;
  eraAtioq(ri, di, &astrom, &aob, &zob, &hob, &dob, &rob);
  Place p;
  p.az_deg = eraAnp(aob) * ERFA_DR2D;
  p.el_geometric_deg = 90.0 - zob * ERFA_DR2D;
  p.ra_deg = eraAnp(ri - epoch.eo_rad) * ERFA_DR2D;
  p.dec_deg = di * ERFA_DR2D;
  return p;
}

/// Observed place of a solar-system body whose barycentric state at the emission time t − τ is
/// `x` (relative vector `r` = X(t−τ) − O(t)).
Place place_of_body(const Epoch& epoch, const Station& st, const Vec3& r, const Vec3& vel_x) {
  eraASTROM astrom = to_astrom(st);
  const double rho_au = norm(r);
  Vec3 u = scale(r, 1.0 / rho_au);
  // d|X(t−τ(t)) − O(t)|/dt with τ = ρ/c: ρ̇ = u·(V_X − V_O) / (1 + u·V_X / c).
  const Vec3 v_obs = observer_velocity_au_d(st);
  const double rate_au_d =
      dot(u, sub(vel_x, v_obs)) / (1.0 + dot(u, vel_x) / kSpeedOfLightAuPerDay);

  double pnat[3] = {u[0], u[1], u[2]};
  double ppr[3];
  eraAb(pnat, astrom.v, astrom.em, astrom.bm1, ppr);
  double pi[3];
  eraRxp(astrom.bpn, ppr, pi);
  double ri = 0, di = 0;
  eraC2s(pi, &ri, &di);
  Place p = place_from_cirs(epoch, astrom, eraAnp(ri), di);
  p.distance_km = rho_au * kKmPerAu;
  p.range_rate_km_s = rate_au_d * kKmPerAu / ERFA_DAYSEC;
  return p;
}

Station station_from(const eraASTROM& a, const Observer& observer) {
  Station st;
  st.observer = observer;
  st.pmt = a.pmt;
  for (int i = 0; i < 3; ++i) {
    st.eb[i] = a.eb[i];
    st.eh[i] = a.eh[i];
    st.v[i] = a.v[i];
    for (int j = 0; j < 3; ++j) st.bpn[i][j] = a.bpn[i][j];
  }
  st.em = a.em;
  st.bm1 = a.bm1;
  st.along = a.along;
  st.phi = a.phi;
  st.xpl = a.xpl;
  st.ypl = a.ypl;
  st.sphi = a.sphi;
  st.cphi = a.cphi;
  st.diurab = a.diurab;
  st.eral = a.eral;
  return st;
}

}  // namespace

Result<Epoch> make_epoch(const Ephemeris& ephemeris, const TimeScales& time) {
  auto earth_sun = ephemeris.earth_sun(time.tt);
  if (!earth_sun) return earth_sun.error();
  Epoch e;
  e.time = time;
  e.earth_sun = *earth_sun;
  const JulianDate& tt = time.tt;
  // IAU 2000B: 77 luni-solar terms, within 1 mas of IAU 2000A 1995–2050 (ERFA nut00b.c) at a
  // twentieth of the cost — far below the 0.1″ budget of the Sun.
  eraPnm00b(tt.jd1, tt.jd2, e.bpn);
  eraBpn2xy(e.bpn, &e.x, &e.y);
  e.s = eraS00(tt.jd1, tt.jd2, e.x, e.y);
  e.sp = eraSp00(tt.jd1, tt.jd2);
  e.era_rad = eraEra00(time.ut1.jd1, time.ut1.jd2);
  e.eo_rad = eraEors(e.bpn, e.s);
  return e;
}

Station make_station(const Epoch& epoch, const Observer& observer) {
  const PosVel& earth = epoch.earth_sun.earth_bary;
  const PosVel& sun = epoch.earth_sun.sun_bary;
  double ebpv[2][3];
  double ehp[3];
  for (std::size_t i = 0; i < 3; ++i) {
    ebpv[0][i] = earth.pos_au[i];
    ebpv[1][i] = earth.vel_au_d[i];
    ehp[i] = earth.pos_au[i] - sun.pos_au[i];
  }
  eraASTROM astrom{};
  // Polar motion is not applied (≈ 0.3″, below every bar here); refraction constants zero.
  eraApco(epoch.time.tt.jd1, epoch.time.tt.jd2, ebpv, ehp, epoch.x, epoch.y, epoch.s, epoch.era_rad,
          observer.lon_deg * ERFA_DD2R, observer.lat_deg * ERFA_DD2R, observer.height_m, 0.0, 0.0,
          epoch.sp, 0.0, 0.0, &astrom);
  return station_from(astrom, observer);
}

Place observe_sun(const Epoch& epoch, const Station& st) {
  const PosVel& sun = epoch.earth_sun.sun_bary;
  const Vec3 obs{st.eb[0], st.eb[1], st.eb[2]};
  // The Sun's barycentric acceleration (< 3e-10 au/day², from the planets) is negligible over τ.
  double tau_d = 0.0;
  PosVel emitted = sun;
  for (int it = 0; it < kLightTimeIterations; ++it) {
    emitted = extrapolate_back(sun, Vec3{}, tau_d);
    tau_d = norm(sub(emitted.pos_au, obs)) / kSpeedOfLightAuPerDay;
  }
  emitted = extrapolate_back(sun, Vec3{}, tau_d);
  return place_of_body(epoch, st, sub(emitted.pos_au, obs), emitted.vel_au_d);
}

namespace {

/// A body given geocentrically, observed with light time in the barycentric frame:
/// X(t−τ) = E(t−τ) + B(t−τ), the Earth carried back from t, the body from `body_at(τ)`. Doing it
/// geocentrically would drop the Earth's own motion during τ (~39 km for the Moon, 20″).
template <typename BodyAt>
Result<Place> observe_geocentric(const Epoch& epoch, const Station& st, const BodyAt& body_at) {
  const PosVel& earth = epoch.earth_sun.earth_bary;
  const Vec3 sun_to_earth = sub(earth.pos_au, epoch.earth_sun.sun_bary.pos_au);
  const Vec3 earth_accel = kepler_acceleration(sun_to_earth, kGmSun);
  const Vec3 obs{st.eb[0], st.eb[1], st.eb[2]};
  double tau_d = 0.0;
  Vec3 r{};
  Vec3 vel_x{};
  for (int it = 0; it <= kLightTimeIterations; ++it) {
    const PosVel e = extrapolate_back(earth, earth_accel, tau_d);
    const Result<PosVel> b = body_at(tau_d);
    if (!b) return b.error();
    r = sub(add(e.pos_au, b->pos_au), obs);
    vel_x = add(e.vel_au_d, b->vel_au_d);
    tau_d = norm(r) / kSpeedOfLightAuPerDay;
  }
  return place_of_body(epoch, st, r, vel_x);
}

}  // namespace

Result<Place> observe_moon(const Ephemeris& ephemeris, const Epoch& epoch, const Station& st) {
  auto moon = ephemeris.moon_geocentric(epoch.time.tt);
  if (!moon) return moon.error();
  const Vec3 moon_accel = kepler_acceleration(moon->pos_au, kGmEarthMoon);
  return observe_geocentric(epoch, st, [&](double tau_d) -> Result<PosVel> {
    return extrapolate_back(*moon, moon_accel, tau_d);
  });
}

Result<Place> observe_tabulated(const SpacecraftTable& table, const Epoch& epoch,
                                const Station& st) {
  // The table is read at the emission time: a deep-space probe's light time is minutes to
  // hours, too long to extrapolate over.
  return observe_geocentric(epoch, st, [&](double tau_d) {
    return table.at(JulianDate{epoch.time.tt.jd1, epoch.time.tt.jd2 - tau_d});
  });
}

Place observe_icrs(const Epoch& epoch, const Station& st, double ra_deg, double dec_deg) {
  eraASTROM astrom = to_astrom(st);
  double ri = 0, di = 0;
  // Space motion zero; eraAtciq applies light deflection by the Sun, aberration and bpn.
  eraAtciq(ra_deg * ERFA_DD2R, dec_deg * ERFA_DD2R, 0.0, 0.0, 0.0, 0.0, &astrom, &ri, &di);
  return place_from_cirs(epoch, astrom, ri, di);
}

double echo_delay_s(double distance_km) { return 2.0 * distance_km / kSpeedOfLightKmS; }

double self_echo_doppler_hz(double freq_mhz, double range_rate_km_s) {
  return -2.0 * freq_mhz * 1e6 * range_rate_km_s / kSpeedOfLightKmS;
}

double dx_echo_doppler_hz(double freq_mhz, double range_rate_a_km_s, double range_rate_b_km_s) {
  return -freq_mhz * 1e6 * (range_rate_a_km_s + range_rate_b_km_s) / kSpeedOfLightKmS;
}

}  // namespace azt::astro
