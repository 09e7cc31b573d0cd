#pragma once

#include <span>
#include <string_view>

namespace azt::astro {

/// An amateur band with the frequency at which EME activity concentrates, for per-band Doppler.
struct AmateurBand {
  std::string_view name;        ///< "144", "10g" …
  double freq_mhz = 0.0;        ///< typical EME frequency in the band
  std::string_view wavelength;  ///< what operators call it: "2 m", "23 cm" …
};

/// 50 MHz to 24 GHz, plus 47 and 76 GHz, in frequency order.
std::span<const AmateurBand> eme_bands();

/// Finds a band by name ("144", "1296", "10g", "10368" …); nullptr if unknown.
const AmateurBand* find_band(std::string_view name);

}  // namespace azt::astro
