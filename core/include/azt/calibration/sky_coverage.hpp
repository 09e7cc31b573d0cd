#pragma once
// How well a set of scans covers the sky for the pointing model (docs/calibration.md): the error
// the fitted model would leave over the sky for one degree of scan noise. Each scan adds what the
// seven terms do to its two offsets there (the first-order sums of pointing_model.hpp); the
// model's expected error at a direction g is gᵀ·N⁻¹·g (N the scans' normal matrix: the variance of
// a least-squares prediction, e.g. Press et al., Numerical Recipes 3rd ed. §15.4), averaged over
// the grid beam_error_over_sky measures on. A planner that picks the scan lowering it most (an
// I-optimal design) spreads the scans in azimuth and elevation as far as the terms need it.

#include <array>
#include <cstddef>

#include "azt/calibration/pointing_model.hpp"
#include "azt/control/modes.hpp"

namespace azt::calibration {

/// How each term, per degree, moves the mount's reading from the source at `sky` (first order):
/// `xel` in cross-elevation (azimuth × cos E), `el` in elevation, in PointingTerms's order.
struct TermPartials {
  std::array<double, PointingTerms::kCount> xel{};
  std::array<double, PointingTerms::kCount> el{};
};
TermPartials term_partials(const control::AzEl& sky);

class SkyCoverage {
 public:
  static constexpr std::size_t kTerms = PointingTerms::kCount;

  /// The sky to cover: azimuth every 15°, elevation `min_el_deg`–`max_el_deg` every 5° (as
  /// beam_error_over_sky).
  explicit SkyCoverage(double min_el_deg = 10.0, double max_el_deg = 80.0);

  /// A scan at `sky`; `weight` scales its information (1: one scan of unit noise). A cross
  /// scan's line alone measures one offset: `xel` or `el` false leaves the other out.
  void add(const control::AzEl& sky, double weight = 1.0, bool xel = true, bool el = true);
  /// Scans' worth added (a line alone is half a scan).
  [[nodiscard]] std::size_t scans() const { return offsets_ / 2; }

  /// The model's expected rms error over the sky per degree of scan noise. Until the scans
  /// determine every term it is dominated by a weak prior (each term known to 1/√kPrior degrees),
  /// so it is finite and falls with every scan that determines something new.
  [[nodiscard]] double sky_error() const;
  /// The same after one more scan at `sky`.
  [[nodiscard]] double sky_error_with(const control::AzEl& sky, double weight = 1.0) const;

  /// The prior's information per term (a term of ±10° is known to ~30° before any scan).
  static constexpr double kPrior = 1e-3;

 private:
  using Matrix = std::array<double, kTerms * kTerms>;
  [[nodiscard]] double error_of(const Matrix& normal) const;
  static void accumulate(Matrix& normal, const control::AzEl& sky, double weight, bool xel = true,
                         bool el = true);

  Matrix normal_{};
  Matrix sky_moments_{};  ///< mean over the grid of x·xᵀ + e·eᵀ
  std::size_t offsets_ = 0;
};

}  // namespace azt::calibration
