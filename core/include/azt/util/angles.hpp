#pragma once
// Degrees and radians: the one conversion constant the core's files share (they used to write
// their own).

#include <numbers>

namespace azt {

inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;

}  // namespace azt
