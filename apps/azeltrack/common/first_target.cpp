#include "common/first_target.hpp"

#include <cstdio>
#include <optional>

namespace azt::app {
namespace {

std::optional<double> elevation_deg(const astro::SkySnapshot& sky, const astro::Target& target) {
  const auto seen = sky.observe(target);
  if (!seen) return std::nullopt;
  return seen->observation.el_deg;
}

std::string el_text(double el_deg) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f°", el_deg);
  return buf;
}

}  // namespace

FirstTarget choose_first_target(const astro::SkySnapshot& sky,
                                const std::vector<astro::Target>& targets, double el_min_deg) {
  const auto moon_el = elevation_deg(sky, astro::Target::moon());
  if (moon_el && *moon_el > el_min_deg) {
    return {"moon", "the Moon is up, at elevation " + el_text(*moon_el)};
  }
  const std::string moon_down =
      "the Moon is below the horizon" + (moon_el ? " (" + el_text(*moon_el) + ")" : std::string());
  const auto sun_el = elevation_deg(sky, astro::Target::sun());
  if (sun_el && *sun_el > el_min_deg) {
    return {"sun", moon_down + "; the Sun is up, at " + el_text(*sun_el)};
  }
  for (const auto& target : targets) {
    if (target.kind != astro::Target::Kind::Source) continue;
    const auto el = elevation_deg(sky, target);
    if (el && *el >= kSourceMinElDeg && *el > el_min_deg) {
      return {target.name,
              moon_down + " and so is the Sun; " + target.name + " is at " + el_text(*el)};
    }
  }
  return {"moon", moon_down + ", the Sun too, and no radio source is " + el_text(kSourceMinElDeg) +
                      " up: the Moon, waiting for moonrise"};
}

}  // namespace azt::app
