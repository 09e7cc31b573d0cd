#pragma once

#include <array>

namespace azt::astro {

using Vec3 = std::array<double, 3>;

/// Position (au) and velocity (au/day) of a body, BCRS/GCRS with ICRS axes, at one TT instant.
struct PosVel {
  Vec3 pos_au{};
  Vec3 vel_au_d{};
};

}  // namespace azt::astro
