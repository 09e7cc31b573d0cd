#include "azt/eme/sky_temperature.hpp"
#include "azt/util/angles.hpp"

#include <array>
#include <cmath>

namespace azt::eme {
namespace {

constexpr double kCmbK = 2.7;
constexpr double kSpectralIndex = 2.6;
constexpr double kTableMhz = 144.0;
constexpr double kColdSkyK = 13.0;  // at 408 MHz
constexpr double kColdSkyMhz = 408.0;

/// Sky temperature at 144 MHz (K) in the ecliptic, bins 1..180 of 2° of ecliptic longitude:
/// the data of WSJT-X's lib/astro.f90 (`nt144`, K1JT et al., GPL-3), derived from the Haslam et
/// al. (1982) 408 MHz survey. The peak near 270°–280° is the galactic centre.
constexpr std::array<short, 180> kTsky144K = {
    234,  246,  257,  267,  275,  280,  283,  286,  291,  298,  305,  313,  322,  331,  341,
    351,  361,  369,  376,  381,  383,  382,  379,  374,  370,  366,  363,  361,  363,  368,
    376,  388,  401,  415,  428,  440,  453,  467,  487,  512,  544,  579,  607,  618,  609,
    588,  563,  539,  512,  482,  450,  422,  398,  379,  363,  349,  334,  319,  302,  282,
    262,  242,  226,  213,  205,  200,  198,  197,  196,  197,  200,  202,  204,  205,  204,
    203,  202,  201,  203,  206,  212,  218,  223,  227,  231,  236,  240,  243,  247,  257,
    276,  301,  324,  339,  346,  344,  339,  331,  323,  316,  312,  310,  312,  317,  327,
    341,  358,  375,  392,  407,  422,  437,  451,  466,  480,  494,  511,  530,  552,  579,
    612,  653,  702,  768,  863,  1008, 1232, 1557, 1966, 2385, 2719, 2924, 3018, 3038, 2986,
    2836, 2570, 2213, 1823, 1461, 1163, 939,  783,  677,  602,  543,  494,  452,  419,  392,
    373,  360,  353,  350,  350,  350,  350,  350,  350,  348,  344,  337,  329,  319,  307,
    295,  284,  276,  272,  272,  273,  274,  274,  271,  266,  260,  252,  245,  238,  231};

}  // namespace

double ecliptic_longitude_deg(double ra_deg, double dec_deg) {
  const double eps = kTskyTableObliquityDeg * kRadPerDeg;
  const double ra = ra_deg * kRadPerDeg;
  const double dec = dec_deg * kRadPerDeg;
  const double lon =
      std::atan2(std::sin(ra) * std::cos(eps) + std::tan(dec) * std::sin(eps), std::cos(ra));
  const double deg = lon / kRadPerDeg;
  return deg < 0.0 ? deg + 360.0 : deg;
}

double tsky_144mhz_k(double ecliptic_lon_deg) {
  long bin = std::lround(ecliptic_lon_deg / 2.0);  // Fortran nint: halves away from zero
  if (bin < 1 || bin > static_cast<long>(kTsky144K.size())) bin = 180;
  return kTsky144K[static_cast<std::size_t>(bin - 1)];
}

double tsky_k(double ecliptic_lon_deg, double freq_mhz) {
  return (tsky_144mhz_k(ecliptic_lon_deg) - kCmbK) *
             std::pow(kTableMhz / freq_mhz, kSpectralIndex) +
         kCmbK;
}

double cold_sky_k(double freq_mhz) {
  return kColdSkyK * std::pow(kColdSkyMhz / freq_mhz, kSpectralIndex);
}

double moon_distance_db(double distance_km) { return -40.0 * std::log10(distance_km / kPerigeeKm); }

double dgrd_db(double tsky, double freq_mhz, double distance_km) {
  const double tsys = tsky + kReceiverK;
  const double tsys_min = cold_sky_k(freq_mhz) + kReceiverK;
  return -10.0 * std::log10(tsys / tsys_min) + moon_distance_db(distance_km);
}

}  // namespace azt::eme
