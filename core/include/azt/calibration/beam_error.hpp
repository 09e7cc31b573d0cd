#pragma once
// How far the beam misses over the sky (docs/calibration.md): a mount that really behaves as
// `actual`, pointed by a controller that believes `model`, sent to a grid of sky directions. With
// the model equal to the mount, the error is zero everywhere; with no model, it is what the mount's
// errors cost the operator.

#include <cstddef>

#include "azt/calibration/pointing_model.hpp"

namespace azt::calibration {

struct BeamError {
  double rms_deg = 0.0;
  double max_deg = 0.0;
  std::size_t directions = 0;
};

/// Over azimuth 0–345° every 15° and elevation `min_el_deg`–`max_el_deg` every 5°: the angle
/// between each direction and where the beam points when the controller believes it points
/// there.
BeamError beam_error_over_sky(const PointingTerms& actual, const PointingTerms& model,
                              double min_el_deg = 10.0, double max_el_deg = 80.0);

/// Absolute encoders' counts, degrees: a count reads the bottom of its step.
struct EncoderSteps {
  double az_deg = 0.0;
  double el_deg = 0.0;
};

/// The same with the encoders in the loop: the controller brings the readings to the model's
/// mount angles, and the shaft may then be anywhere in the count (averaged over a 16 × 16 grid
/// of places in it). A model fitted from scans read by these encoders takes their half step in.
BeamError beam_error_with_encoders(const PointingTerms& actual, const PointingTerms& model,
                                   const EncoderSteps& steps, double min_el_deg = 10.0,
                                   double max_el_deg = 80.0);

/// The least error over the sky any model leaves with these encoders: the shaft is uniform
/// within a count, q/√12 rms per axis about its middle, on the sky √(q_az²·cos²E + q_el²)/√12,
/// rms over the grid.
double quantisation_floor_deg(const EncoderSteps& steps, double min_el_deg = 10.0,
                              double max_el_deg = 80.0);

}  // namespace azt::calibration
