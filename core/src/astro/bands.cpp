// Amateur bands from 6 m to 4 mm with the frequency where EME activity concentrates (the usual
// EME segments of the IARU band plans; 13 cm and 9 cm vary by region, we take the common
// international segment).
#include "azt/astro/bands.hpp"

#include <array>
#include <cctype>
#include <string>

namespace azt::astro {
namespace {

const std::array<AmateurBand, 14> kBands{{
    {"50", 50.190, "6 m"},
    {"70", 70.200, "4 m"},
    {"144", 144.100, "2 m"},
    {"222", 222.100, "1.25 m"},
    {"432", 432.100, "70 cm"},
    {"902", 903.100, "33 cm"},
    {"1296", 1296.100, "23 cm"},
    {"2304", 2304.100, "13 cm"},
    {"3400", 3400.100, "9 cm"},
    {"5760", 5760.100, "6 cm"},
    {"10368", 10368.100, "3 cm"},
    {"24048", 24048.100, "1.2 cm"},
    {"47088", 47088.100, "6 mm"},
    {"76032", 76032.100, "4 mm"},
}};

struct Alias {
  std::string_view alias;
  std::string_view band;
};
// What operators also call the bands besides their wavelengths.
const std::array<Alias, 6> kAliases{{
    {"10g", "10368"},
    {"24g", "24048"},
    {"47g", "47088"},
    {"76g", "76032"},
    {"3.4g", "3400"},
    {"5.7g", "5760"},
}};

/// "2 m" as typed: no spaces, lower case.
std::string squeezed(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c != ' ') out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return out;
}

}  // namespace

std::span<const AmateurBand> eme_bands() { return kBands; }

const AmateurBand* find_band(std::string_view text) {
  const std::string typed = squeezed(text);
  std::string_view name = typed;
  for (const auto& a : kAliases) {
    if (a.alias == name) name = a.band;
  }
  for (const auto& b : kBands) {
    if (b.name == name || squeezed(b.wavelength) == name) return &b;
  }
  return nullptr;
}

}  // namespace azt::astro
