// Calibration and star-noise radio sources. Positions are ICRS (J2000); provenance per entry.
// Flux densities: Perley & Butler 2017, ApJS 230, 7, table 5 polynomial fits evaluated at the band
// frequency (values from ../shared/reference/astronomy-and-eme.md §5); entries outside the fitted
// range are extrapolations and say so in flux_ref.
//
// The AnTrack-Pro buttons (seed 000) name constellations; an EME operator means the bright radio
// source in each: Sagittarius = Sgr A (Galactic Centre), Cassiopeia = Cas A, Taurus = Tau A (Crab),
// Pictor = Pictor A. Leo holds no strong radio source; the button's useful meaning is the brightest
// source of that part of the spring sky, Virgo A (M87, 10° east of Leo's tail star Denebola), so
// "leo" is an alias of Virgo A.
#include "azt/astro/catalogue.hpp"

#include <array>
#include <cctype>
#include <string>

namespace azt::astro {
namespace {

constexpr double hms(double h, double m, double s) { return 15.0 * (h + m / 60.0 + s / 3600.0); }
constexpr double dms(double sign, double d, double m, double s) {
  return sign * (d + m / 60.0 + s / 3600.0);
}

constexpr std::string_view kPb17 = "Perley & Butler 2017 (ApJS 230, 7)";
constexpr std::string_view kPb17Extrapolated =
    "Perley & Butler 2017 (ApJS 230, 7); 10 GHz value extrapolated beyond the fitted range";

const std::array<RadioSource, 12> kSources{{
    {"casa", "Cassiopeia A", "cassiopeia,cas a,3c461", hms(23, 23, 24.0), dms(+1, 58, 48, 54.0),
     "supernova remnant, 5′; fading ~0.6 %/yr",
     "SNR centre as listed by Baars et al. 1977 / KAIRA A-team list", 1876.0, 1196.0, 305.0,
     kPb17Extrapolated},
    {"cyga", "Cygnus A", "cygnus,cyg a,3c405", hms(19, 59, 28.35663), dms(+1, 40, 44, 2.0970),
     "radio galaxy, 2′", "ICRF core position (VLBA calibrator list)", 1714.0, 909.0, 148.0, kPb17},
    {"taua", "Taurus A", "taurus,tau a,crab,m1,3c144", hms(5, 34, 31.94), dms(+1, 22, 0, 52.2),
     "Crab Nebula supernova remnant, 5′×7′", "Crab pulsar position (SIMBAD)", 844.0, 730.0, 410.0,
     kPb17Extrapolated},
    {"vira", "Virgo A", "virgo,vir a,m87,3c274,leo", hms(12, 30, 49.42338),
     dms(+1, 12, 23, 28.0439), "radio galaxy M87 with a 10′ halo", "ICRF3 core position", 226.0,
     140.0, 37.0, kPb17Extrapolated},
    {"sgra",
     "Sagittarius A",
     "sagittarius,sgr a,sgr a*,galactic centre,galactic center",
     hms(17, 45, 40.0409),
     dms(-1, 29, 0, 28.118),
     "Galactic Centre complex around Sgr A*, extended over ~1°",
     "Sgr A* (Reid & Brunthaler 2004, ApJ 616, 872)",
     std::nullopt,
     std::nullopt,
     std::nullopt,
     {}},
    {"pica", "Pictor A", "pictor,pic a", hms(5, 19, 49.7229), dms(-1, 45, 46, 43.853),
     "radio galaxy, 8′ lobes", "core position (ATCA calibrator list)", 71.0, 45.0, 13.0,
     kPb17Extrapolated},
    {"oria",
     "Orion A",
     "orion,ori a,m42,orion nebula",
     hms(5, 35, 17.3),
     dms(-1, 5, 23, 28.0),
     "thermal H II region (Orion Nebula), ~5′",
     "M42 (SIMBAD)",
     std::nullopt,
     std::nullopt,
     std::nullopt,
     {}},
    {"hyda", "Hydra A", "hydra,hyd a,3c218", hms(9, 18, 5.651), dms(-1, 12, 5, 43.99),
     "radio galaxy, 8′", "core position (VLA calibrator list)", 47.0, 27.0, 6.0, kPb17},
    {"hera", "Hercules A", "hercules,her a,3c348", hms(16, 51, 8.147), dms(+1, 4, 59, 33.32),
     "radio galaxy, 3′", "core position (NED)", 52.0, 28.0, 5.0, kPb17},
    {"cena",
     "Centaurus A",
     "centaurus,cen a,ngc5128",
     hms(13, 25, 27.6),
     dms(-1, 43, 1, 9.0),
     "radio galaxy, inner lobes 10′, outer lobes ~8°",
     "core position (SIMBAD)",
     std::nullopt,
     std::nullopt,
     std::nullopt,
     {}},
    {"m17",
     "Omega Nebula (M17)",
     "omega,omega nebula",
     hms(18, 20, 26.0),
     dms(-1, 16, 10, 36.0),
     "thermal H II region, ~10′",
     "M17 (SIMBAD)",
     std::nullopt,
     std::nullopt,
     std::nullopt,
     {}},
    {"3c273",
     "3C 273",
     "3c 273",
     hms(12, 29, 6.6997),
     dms(+1, 2, 3, 8.598),
     "quasar, point-like, variable",
     "ICRF3 position",
     std::nullopt,
     std::nullopt,
     std::nullopt,
     {}},
}};

/// Lower-case letters and digits only: "Sgr A*" and "sgra" compare equal.
std::string normalise(std::string_view text) {
  std::string out;
  for (char c : text) {
    const auto uc = static_cast<unsigned char>(c);
    if (std::isalnum(uc) != 0) out.push_back(static_cast<char>(std::tolower(uc)));
  }
  return out;
}

bool matches(const RadioSource& s, const std::string& wanted) {
  if (normalise(s.key) == wanted || normalise(s.name) == wanted) return true;
  std::string_view rest = s.aliases;
  while (!rest.empty()) {
    const auto comma = rest.find(',');
    if (normalise(rest.substr(0, comma)) == wanted) return true;
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return false;
}

}  // namespace

std::span<const RadioSource> radio_sources() { return kSources; }

const RadioSource* find_radio_source(std::string_view name) {
  const std::string wanted = normalise(name);
  if (wanted.empty()) return nullptr;
  for (const auto& s : kSources) {
    if (matches(s, wanted)) return &s;
  }
  return nullptr;
}

}  // namespace azt::astro
