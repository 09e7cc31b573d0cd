#pragma once
// What a source asks the antenna to point at, parsed once (docs/daemon.md): the console's body, a
// PC program's position and the configuration's start target all become one of these, and only
// the station's front door (station_commands.hpp) decides what it means for the modes.

#include <string>
#include <string_view>
#include <variant>

namespace azt::app {

/// A configured target by name: the Sun, the Moon, a radio source or a spacecraft table
/// (case-blind: "moon", "casa", "Cassiopeia A").
struct NamedTarget {
  std::string name;
};
/// A satellite of the catalogue by name or NORAD number ("sat:ISS", "sat:25544").
struct SatelliteTarget {
  std::string name_or_norad;
};
/// A fixed point of the sky, J2000 degrees.
struct RaDecTarget {
  double ra_deg = 0.0;
  double dec_deg = 0.0;
};
/// One of the four park slots, 1 to 4.
struct ParkTarget {
  long long slot = 1;
};
/// A position: sky azimuth in any client convention (−180…450), elevation up from the horizon.
/// From the console it is MAN mode; from a PC program it is EXT mode.
struct PositionTarget {
  double az_deg = 0.0;
  double el_deg = 0.0;
};

using TargetRequest =
    std::variant<NamedTarget, SatelliteTarget, RaDecTarget, ParkTarget, PositionTarget>;

/// The prefix that names a satellite rather than a configured target.
inline constexpr std::string_view kSatellitePrefix = "sat:";

/// A target given by name, as in `[target] name` or the console's target list: "sat:NAME" is a
/// satellite, anything else a configured target.
TargetRequest target_from_name(std::string_view name);

/// The name a tracked satellite is shown under ("sat:ISS (ZARYA)").
std::string satellite_display_name(std::string_view catalogue_name);

}  // namespace azt::app
