#pragma once
// Cubic Hermite interpolation of a state between two tabulated nodes: the interpolator of the
// ephemeris tables (tabulated_ephemeris.hpp) and of JPL Horizons vector tables (horizons.hpp).

#include "azt/astro/vec3.hpp"

namespace azt::astro {

/// The state between nodes `a` and `b`, `h` days apart, at s ∈ [0, 1]: position from the basis
/// polynomials, velocity from their derivatives divided by h.
PosVel hermite(const PosVel& a, const PosVel& b, double h, double s);

}  // namespace azt::astro
