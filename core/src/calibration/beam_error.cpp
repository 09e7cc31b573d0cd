#include "azt/calibration/beam_error.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace azt::calibration {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr int kPlacesPerAxis = 16;  ///< where in its count the shaft may be

/// Over the grid of beam_error_over_sky: `miss_sq` gives each direction's squared error
/// (nullopt: the direction is not reachable).
BeamError over_grid(double min_el_deg, double max_el_deg,
                    const std::function<std::optional<double>(const control::AzEl&)>& miss_sq) {
  BeamError out;
  double sum_sq = 0.0;
  for (int az_step = 0; az_step < 24; ++az_step) {
    for (int el_step = 0; min_el_deg + 5.0 * el_step <= max_el_deg + 1e-9; ++el_step) {
      const auto sq = miss_sq({15.0 * az_step, min_el_deg + 5.0 * el_step});
      if (!sq) continue;
      sum_sq += *sq;
      out.max_deg = std::max(out.max_deg, std::sqrt(*sq));
      ++out.directions;
    }
  }
  if (out.directions > 0) out.rms_deg = std::sqrt(sum_sq / static_cast<double>(out.directions));
  return out;
}

}  // namespace

BeamError beam_error_over_sky(const PointingTerms& actual, const PointingTerms& model,
                              double min_el_deg, double max_el_deg) {
  return over_grid(min_el_deg, max_el_deg, [&](const control::AzEl& sky) -> std::optional<double> {
    // The controller drives the mount until its model says the beam is on `sky`.
    const auto mount = mount_for_sky(sky, model);
    if (!mount) return std::nullopt;
    const double miss = separation_deg(sky, beam_on_sky(*mount, actual));
    return miss * miss;
  });
}

BeamError beam_error_with_encoders(const PointingTerms& actual, const PointingTerms& model,
                                   const EncoderSteps& steps, double min_el_deg,
                                   double max_el_deg) {
  return over_grid(min_el_deg, max_el_deg, [&](const control::AzEl& sky) -> std::optional<double> {
    const auto mount = mount_for_sky(sky, model);
    if (!mount) return std::nullopt;
    double sum = 0.0;
    for (int i = 0; i < kPlacesPerAxis; ++i) {
      for (int j = 0; j < kPlacesPerAxis; ++j) {
        const control::AzEl shaft{mount->az_deg + steps.az_deg * (i + 0.5) / kPlacesPerAxis,
                                  mount->el_deg + steps.el_deg * (j + 0.5) / kPlacesPerAxis};
        const double miss = separation_deg(sky, beam_on_sky(shaft, actual));
        sum += miss * miss;
      }
    }
    return sum / (kPlacesPerAxis * kPlacesPerAxis);
  });
}

double quantisation_floor_deg(const EncoderSteps& steps, double min_el_deg, double max_el_deg) {
  return over_grid(min_el_deg, max_el_deg,
                   [&](const control::AzEl& sky) -> std::optional<double> {
                     const double c = std::cos(sky.el_deg * kDegToRad);
                     return (steps.az_deg * steps.az_deg * c * c + steps.el_deg * steps.el_deg) /
                            12.0;
                   })
      .rms_deg;
}

}  // namespace azt::calibration
