#include "azt/sim/brake_plant.hpp"

#include <algorithm>
#include <cmath>

namespace azt::sim {

Result<BrakePlantParams> BrakePlantParams::validate() const {
  if (!std::isfinite(release_s) || release_s <= 0.0 || release_s > 60.0) {
    return fail("release_s must be above 0 and at most 60 s");
  }
  if (!std::isfinite(engage_s) || engage_s <= 0.0 || engage_s > 60.0) {
    return fail("engage_s must be above 0 and at most 60 s");
  }
  return *this;
}

double BrakePlant::step(bool energised, double duty, double dt_s) {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) return 0.0;
  // The shaft is free for this step only if the brake was off at its start and stays off.
  const bool free_at_start = released();
  const double change = energised ? dt_s / params_.release_s : -dt_s / params_.engage_s;
  progress_ = std::clamp(progress_ + change, 0.0, 1.0);
  const bool free = free_at_start && released();
  const bool driven = std::isfinite(duty) && duty != 0.0;
  if (driven && !free) {
    pulled_against_s_ += dt_s;
    ++pulled_against_steps_;
  }
  return free && driven ? duty : 0.0;
}

}  // namespace azt::sim
