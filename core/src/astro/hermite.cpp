#include "azt/astro/hermite.hpp"

#include <cstddef>

namespace azt::astro {

PosVel hermite(const PosVel& a, const PosVel& b, double h, double s) {
  const double s2 = s * s;
  const double s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s;
  const double h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1;
  const double d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
  PosVel out;
  for (std::size_t i = 0; i < 3; ++i) {
    const double pa = a.pos_au[i], pb = b.pos_au[i];
    const double va = a.vel_au_d[i] * h, vb = b.vel_au_d[i] * h;
    out.pos_au[i] = h00 * pa + h10 * va + h01 * pb + h11 * vb;
    out.vel_au_d[i] = (d00 * pa + d10 * va + d01 * pb + d11 * vb) / h;
  }
  return out;
}

}  // namespace azt::astro
