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
    {"50", 50.190},
    {"70", 70.200},
    {"144", 144.100},
    {"222", 222.100},
    {"432", 432.100},
    {"902", 903.100},
    {"1296", 1296.100},
    {"2304", 2304.100},
    {"3400", 3400.100},
    {"5760", 5760.100},
    {"10368", 10368.100},
    {"24048", 24048.100},
    {"47088", 47088.100},
    {"76032", 76032.100},
}};

struct Alias {
  std::string_view alias;
  std::string_view band;
};
// What operators also call the bands.
const std::array<Alias, 18> kAliases{{
    {"6m", "50"},
    {"4m", "70"},
    {"2m", "144"},
    {"1.25m", "222"},
    {"70cm", "432"},
    {"33cm", "902"},
    {"23cm", "1296"},
    {"13cm", "2304"},
    {"9cm", "3400"},
    {"6cm", "5760"},
    {"3cm", "10368"},
    {"10g", "10368"},
    {"1.2cm", "24048"},
    {"24g", "24048"},
    {"47g", "47088"},
    {"76g", "76032"},
    {"3.4g", "3400"},
    {"5.7g", "5760"},
}};

}  // namespace

std::span<const AmateurBand> eme_bands() { return kBands; }

const AmateurBand* find_band(std::string_view text) {
  std::string lowered(text);
  for (char& c : lowered) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string_view name = lowered;
  for (const auto& a : kAliases) {
    if (a.alias == name) name = a.band;
  }
  for (const auto& b : kBands) {
    if (b.name == name) return &b;
  }
  return nullptr;
}

}  // namespace azt::astro
