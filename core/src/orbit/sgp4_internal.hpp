#pragma once
// Shared between the SGP4 source files: the WGS-72 constants and the deep-space steps
// (Vallado et al. 2006: dscom + dsinit at initialisation, dspace and dpper while propagating).

#include <numbers>

#include "azt/orbit/sgp4.hpp"

namespace azt::orbit::sgp4_detail {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kTwoThirds = 2.0 / 3.0;

/// WGS-72 as SGP4 uses it (Spacetrack Report #3; the 2006 paper's "wgs72" choice).
struct Gravity {
  double radius_km;  ///< equatorial radius
  double mu_km3_s2;
  double xke;  ///< sqrt(GM) in Earth radii^1.5 per minute
  double j2, j3, j4, j3oj2;
};
const Gravity& wgs72();

/// Greenwich mean sidereal angle (IAU 1982) of a UT1 Julian date, rad in [0, 2π).
double gmst_1982(double jd_ut1);

/// Fills `model.ds` for a deep-space orbit: dscom (Sun and Moon at epoch) then dsinit (secular
/// rates and resonance set-up). Needs the near-earth rates mdot, argpdot, nodedot already set.
void init_deep_space(Sgp4Model& model);

/// The mean elements dspace gives at `t_min`: secular lunar-solar drift plus, for resonant
/// orbits, the integrated mean motion and mean anomaly.
struct DeepMean {
  double em, argpm, inclm, mm, nodem, nm;
};
DeepMean deep_space_secular(const Sgp4Model& model, double t_min, const DeepMean& near_earth);

/// dpper: lunar-solar periodics added to the osculating-to-be elements at `t_min`.
struct Perturbed {
  double ep, inclp, nodep, argpp, mp;
};
Perturbed deep_space_periodics(const Sgp4Model& model, double t_min, const Perturbed& in);

}  // namespace azt::orbit::sgp4_detail
