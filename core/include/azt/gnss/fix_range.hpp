#pragma once
// Whether a GPS fix names a place on the Earth (docs/gps.md; a longitude of 500 from gpsd had
// once been wrapped to 140 and saved as the station's position). A coordinate out of its range is
// refused, never wrapped: a receiver or a gpsd that says 500° says nothing trustworthy about the
// other numbers either.

#include <optional>
#include <string>

#include "azt/gnss/gps_fix.hpp"

namespace azt::gnss {

/// Heights a ground station can have (metres above mean sea level): the Dead Sea shore is at
/// -430 m and the highest observatories near 5,600 m; beyond these a fix is an error.
constexpr double kLowestStationAltM = -1000.0;
constexpr double kHighestStationAltM = 10000.0;

/// Why the fix's place is not on the Earth (latitude outside [-90, 90], longitude outside
/// [-180, 180], a non-finite value, an altitude outside the station range); nullopt if it is.
/// A fix without a place (mode None) is never out of range.
std::optional<std::string> out_of_range(const GpsFix& fix);

}  // namespace azt::gnss
