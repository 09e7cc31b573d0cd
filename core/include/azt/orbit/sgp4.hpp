#pragma once
// SGP4 with the SDP4 deep-space terms (lunar-solar perturbations, 12 h and 24 h resonances), as
// published in Vallado, Crawford, Hujsak, Kelso, "Revisiting Spacetrack Report #3",
// AIAA 2006-6753 (2006), with the corrections the 2020 release of the authors' code carries.
// WGS-72 constants and the "improved" operation mode ('i'), which is what the verification
// output tcppver.out holds (python-sgp4's tests regenerate it with opsmode 'i').
//
// Output is the TEME frame (true equator, mean equinox of date): km and km/s. Time is minutes
// since the element set's epoch, or a UTC Julian date, as SGP4 has always been fed.
//
// Unlike the reference code, propagation does not write to the satellite record (the
// resonance integrator restarts from epoch on every call), so one Sgp4 serves any number of
// callers, in any time order, and gives the same answer for the same time.

#include <array>

#include "azt/orbit/elements.hpp"
#include "azt/util/result.hpp"

namespace azt::orbit {

struct TemeState {
  std::array<double, 3> r_km{};
  std::array<double, 3> v_km_s{};
};

/// Lunar-solar and resonance terms of a deep-space orbit (period ≥ 225 min), fixed at
/// initialisation. Names are the paper's (dscom, dsinit), so the code can be read beside it.
struct Sgp4DeepSpace {
  enum class Resonance { None, OneDay, HalfDay };  ///< irez 0, 1 (synchronous), 2 (Molniya)
  Resonance resonance = Resonance::None;
  // Lunar-solar long-period periodics (dpper), solar then lunar.
  double se2 = 0, se3 = 0, si2 = 0, si3 = 0, sl2 = 0, sl3 = 0, sl4 = 0;
  double sgh2 = 0, sgh3 = 0, sgh4 = 0, sh2 = 0, sh3 = 0;
  double ee2 = 0, e3 = 0, xi2 = 0, xi3 = 0, xl2 = 0, xl3 = 0, xl4 = 0;
  double xgh2 = 0, xgh3 = 0, xgh4 = 0, xh2 = 0, xh3 = 0;
  double zmol = 0, zmos = 0;  ///< lunar and solar mean anomalies at epoch, rad
  // Lunar-solar secular rates, per minute.
  double dedt = 0, didt = 0, dmdt = 0, dnodt = 0, domdt = 0;
  // Resonance coefficients: 12 h (d2201 … d5433) and 24 h (del1 … del3).
  double d2201 = 0, d2211 = 0, d3210 = 0, d3222 = 0, d4410 = 0, d4422 = 0;
  double d5220 = 0, d5232 = 0, d5421 = 0, d5433 = 0;
  double del1 = 0, del2 = 0, del3 = 0;
  double xfact = 0, xlamo = 0;  ///< mean-longitude rate offset, resonance angle at epoch
};

/// Everything SGP4 derives once from an element set (sgp4init), in its units: radians,
/// radians per minute, Earth radii.
struct Sgp4Model {
  double epoch_days_1950 = 0.0;  ///< days since 1949 Dec 31 0h UTC (the paper's "epoch")
  double bstar = 0.0;
  double ecco = 0.0, argpo = 0.0, inclo = 0.0, mo = 0.0, nodeo = 0.0;
  double no_kozai = 0.0;    ///< mean motion as in the TLE, rad/min
  double no_unkozai = 0.0;  ///< Brouwer mean motion, rad/min
  bool simple = false;      ///< isimp: perigee below 220 km, or deep space (drop d2…t5cof)
  bool deep = false;        ///< period ≥ 225 min
  double gsto = 0.0;        ///< Greenwich sidereal angle at epoch (IAU 1982), rad
  double aycof = 0, con41 = 0, cc1 = 0, cc4 = 0, cc5 = 0, d2 = 0, d3 = 0, d4 = 0;
  double delmo = 0, eta = 0, argpdot = 0, omgcof = 0, sinmao = 0;
  double t2cof = 0, t3cof = 0, t4cof = 0, t5cof = 0;
  double x1mth2 = 0, x7thm1 = 0, mdot = 0, nodedot = 0, xlcof = 0, xmcof = 0, nodecf = 0;
  Sgp4DeepSpace ds;
};

class Sgp4 {
 public:
  /// Initialises from mean elements (a TLE's or an OMM's). Errors: eccentricity outside
  /// 0 ≤ e < 1, mean motion ≤ 0, inclination outside 0–180°, a non-finite value.
  static Result<Sgp4> make(const Elements& elements);

  /// The TEME state `minutes` after the epoch (negative: before). Errors are the algorithm's:
  /// mean eccentricity out of range (1), mean motion below zero (2), perturbed eccentricity out
  /// of range (3), semi-latus rectum below zero (4), decayed: below the Earth's surface (6).
  [[nodiscard]] Result<TemeState> at_minutes(double minutes_since_epoch) const;
  /// The TEME state at a UTC Julian date given as whole + fraction (any split).
  [[nodiscard]] Result<TemeState> at_jd(double jd_whole, double jd_frac) const;

  [[nodiscard]] const Elements& elements() const { return elements_; }
  [[nodiscard]] bool deep_space() const { return model_.deep; }
  [[nodiscard]] const Sgp4Model& model() const { return model_; }

 private:
  Sgp4(Elements elements, const Sgp4Model& model);
  Elements elements_;
  Sgp4Model model_;
};

}  // namespace azt::orbit
