#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "azt/astro/catalogue.hpp"
#include "azt/astro/ephemeris.hpp"
#include "azt/astro/horizons.hpp"
#include "azt/astro/refraction.hpp"
#include "azt/astro/sky.hpp"
#include "azt/util/result.hpp"

namespace azt::astro {

/// Something in the sky the antenna can follow.
struct Target {
  enum class Kind { Sun, Moon, Source, RaDec, Spacecraft };
  Kind kind = Kind::Moon;
  std::string name;                     ///< display name
  const RadioSource* source = nullptr;  ///< for Kind::Source
  double ra_deg = 0.0;                  ///< ICRS/J2000, for Source and RaDec
  double dec_deg = 0.0;
  /// Kind::Spacecraft: geocentric states from a JPL Horizons vector table (seed 000's DSN page),
  /// shared by every copy of the target; what it is, and the frequency to listen on.
  std::shared_ptr<const SpacecraftTable> table;
  std::string description;
  double frequency_mhz = 0.0;

  static Target sun();
  static Target moon();
  static Target radio_source(const RadioSource& source);
  static Target spacecraft(std::string name, std::shared_ptr<const SpacecraftTable> table,
                           std::string description, double frequency_mhz);
  /// RA in [0, 360), Dec in [−90, 90]; error otherwise.
  static Result<Target> radec(double ra_deg, double dec_deg);
};

/// Parses what a user types: `sun`, `moon`, a catalogue name or alias (`casa`, `Cassiopeia A`),
/// or `radec:RA_DEG,DEC_DEG` (J2000 degrees). Error names the unknown target and lists how to see
/// the catalogue.
Result<Target> parse_target(std::string_view text);

/// A target as seen from a station, with refraction applied.
struct Observation {
  Place place;
  double el_deg = 0.0;  ///< refracted (apparent) elevation; equals el_geometric_deg for model None
};

Result<Observation> observe(const Target& target, const Ephemeris& ephemeris, const Epoch& epoch,
                            const Station& station, const Atmosphere& atmosphere);

}  // namespace azt::astro
