#pragma once
// What a first start tracks. The default configuration names the Moon, but a new user whose
// Moon is below the horizon would see an antenna that sits still under TRACK; the first start
// instead picks something that is up, and says which and why.

#include <string>
#include <vector>

#include "azt/astro/sky_snapshot.hpp"
#include "azt/astro/target.hpp"

namespace azt::app {

struct FirstTarget {
  std::string name;  ///< as `[target] name` takes it: "moon", "sun", or a catalogue source's name
  std::string why;   ///< one sentence for the log
};

/// The Moon if it is above `el_min_deg`, else the Sun, else the first radio source of `targets`
/// at least `kSourceMinElDeg` up (higher than the horizon limit: a source's noise needs a clear
/// sky), else the Moon, which the console then shows waiting for moonrise.
FirstTarget choose_first_target(const astro::SkySnapshot& sky,
                                const std::vector<astro::Target>& targets, double el_min_deg);

inline constexpr double kSourceMinElDeg = 20.0;

}  // namespace azt::app
