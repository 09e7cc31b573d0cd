#pragma once

#include <optional>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/horizons.hpp"
#include "azt/astro/observer.hpp"
#include "azt/astro/refraction.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/util/result.hpp"

namespace azt::astro {

/// Observer-independent quantities for one instant, shared by every target and station:
/// the Earth and Sun from the ephemeris, IAU 2000B precession-nutation (≤ 1 mas from 2000A
/// 1995–2050), the CIO locator s and the Earth rotation angle.
struct Epoch {
  TimeScales time;
  EarthSun earth_sun;
  double bpn[3][3]{};  ///< GCRS → CIRS (bias-precession-nutation) matrix
  double x = 0.0;      ///< CIP X, Y (rad)
  double y = 0.0;
  double s = 0.0;        ///< CIO locator (rad)
  double sp = 0.0;       ///< TIO locator (rad)
  double era_rad = 0.0;  ///< Earth rotation angle of UT1
  double eo_rad = 0.0;   ///< equation of the origins: RA(equinox) = RA(CIO) − eo
};

Result<Epoch> make_epoch(const Ephemeris& ephemeris, const TimeScales& time);

/// Station-dependent quantities at one Epoch (ERFA's eraASTROM context, no refraction: that is
/// applied separately so the radio model can replace ERFA's optical one).
struct Station {
  Observer observer;
  // eraASTROM fields (see erfa.h); kept here so the header does not drag erfa.h in.
  double pmt = 0.0;
  double eb[3]{};    ///< observer barycentric position (au)
  double eh[3]{};    ///< Sun → observer unit vector
  double em = 0.0;   ///< Sun → observer distance (au)
  double v[3]{};     ///< observer barycentric velocity (units of c)
  double bm1 = 0.0;  ///< sqrt(1 − |v|²)
  double bpn[3][3]{};
  double along = 0.0, phi = 0.0, xpl = 0.0, ypl = 0.0, sphi = 0.0, cphi = 0.0, diurab = 0.0,
         eral = 0.0;
};

Station make_station(const Epoch& epoch, const Observer& observer);

/// An apparent topocentric place, before refraction.
struct Place {
  double az_deg = 0.0;            ///< from north, through east, [0, 360)
  double el_geometric_deg = 0.0;  ///< airless elevation (with aberration, without refraction)
  double ra_deg = 0.0;            ///< apparent topocentric RA, true equator and equinox of date
  double dec_deg = 0.0;           ///< apparent topocentric declination
  /// One-way light-time distance in the barycentric frame |X(t−τ) − O(t)|; none for stars.
  std::optional<double> distance_km;
  /// Exact time derivative of distance_km (km/s, positive receding); none for stars.
  std::optional<double> range_rate_km_s;
};

/// The Sun's centre, light time (barycentric frame), annual + diurnal aberration.
Place observe_sun(const Epoch& epoch, const Station& station);
/// The Moon's centre, light time (barycentric frame), annual + diurnal aberration.
Result<Place> observe_moon(const Ephemeris& ephemeris, const Epoch& epoch, const Station& station);
/// A fixed ICRS direction (J2000 catalogue place): light deflection by the Sun, aberration.
/// A body from a geocentric table (a JPL Horizons vector file): its state at the emission time
/// t − τ read from the table, the Earth carried back as for the Moon, so light time, aberration
/// and parallax are those of the Moon's path. Errors outside the table's span.
Result<Place> observe_tabulated(const SpacecraftTable& table, const Epoch& epoch,
                                const Station& station);

Place observe_icrs(const Epoch& epoch, const Station& station, double ra_deg, double dec_deg);

/// Echo delay (s) for a one-way distance.
double echo_delay_s(double distance_km);
/// Self-echo Doppler (Hz): −2·f·ṙ/c.
double self_echo_doppler_hz(double freq_mhz, double range_rate_km_s);
/// Doppler of an echo from station A heard at station B (Hz): −f·(ṙ_A + ṙ_B)/c.
double dx_echo_doppler_hz(double freq_mhz, double range_rate_a_km_s, double range_rate_b_km_s);

}  // namespace azt::astro
