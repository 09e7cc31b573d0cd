#include "azt/calibration/beam_error.hpp"

#include <algorithm>
#include <cmath>

namespace azt::calibration {

BeamError beam_error_over_sky(const PointingTerms& actual, const PointingTerms& model,
                              double min_el_deg, double max_el_deg) {
  BeamError out;
  double sum_sq = 0.0;
  for (int az_step = 0; az_step < 24; ++az_step) {
    for (int el_step = 0; min_el_deg + 5.0 * el_step <= max_el_deg + 1e-9; ++el_step) {
      const control::AzEl sky{15.0 * az_step, min_el_deg + 5.0 * el_step};
      // The controller drives the mount until its model says the beam is on `sky`.
      const auto mount = mount_for_sky(sky, model);
      if (!mount) continue;
      const double miss = separation_deg(sky, beam_on_sky(*mount, actual));
      sum_sq += miss * miss;
      out.max_deg = std::max(out.max_deg, miss);
      ++out.directions;
    }
  }
  if (out.directions > 0) out.rms_deg = std::sqrt(sum_sq / static_cast<double>(out.directions));
  return out;
}

}  // namespace azt::calibration
