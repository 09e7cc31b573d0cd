#pragma once
// The sky behind the Moon and what it costs an EME path (docs/eme.md), with WSJT-X's
// definitions so that the numbers match the Astronomical Data window operators know
// (WSJTX/wsjtx lib/astro.f90):
//  - Tsky: the sky temperature at 144 MHz along the ecliptic, in 2° steps of the Moon's
//    ecliptic longitude (WSJT-X's table, from the 408 MHz all-sky survey of Haslam et al. 1982),
//    scaled to the band with the spectral index −2.6, the 2.7 K cosmic background not scaled;
//  - Dgrd: the degradation (dB, ≤ about 0) against the best case, the Moon at perigee
//    (356903 km) in the coldest sky (13 K at 408 MHz, scaled the same way), with an 80 K receiver:
//    Dgrd = −10·log10((Tsky + 80)/(Tsky,min + 80)) − 40·log10(d/356903).

namespace azt::eme {

/// The obliquity WSJT-X's table is binned with (its ecliptic pole at declination 1.161639 rad).
inline constexpr double kTskyTableObliquityDeg = 90.0 - 66.55689;
inline constexpr double kPerigeeKm = 356903.0;
inline constexpr double kReceiverK = 80.0;  ///< WSJT-X's "good preamp"

/// Ecliptic longitude (degrees, [0, 360)) of an apparent RA/Dec of date, with the table's
/// obliquity.
double ecliptic_longitude_deg(double ra_deg, double dec_deg);

/// The 144 MHz sky temperature (K) at an ecliptic longitude: the table's value for the 2° bin
/// round(λ/2), bin 180 for λ within 1° of 0°.
double tsky_144mhz_k(double ecliptic_lon_deg);

/// Tsky (K) at `freq_mhz` from the 144 MHz value: (T144 − 2.7)·(144/f)^2.6 + 2.7.
double tsky_k(double ecliptic_lon_deg, double freq_mhz);

/// The coldest sky at `freq_mhz` (K): 13·(408/f)^2.6.
double cold_sky_k(double freq_mhz);

/// The Moon's distance against perigee (dB, 0 at perigee, about −2.3 at apogee): r⁻⁴ path loss.
double moon_distance_db(double distance_km);

/// Dgrd (dB) for a sky temperature at `freq_mhz` and a topocentric Moon distance.
double dgrd_db(double tsky_k, double freq_mhz, double distance_km);

}  // namespace azt::eme
