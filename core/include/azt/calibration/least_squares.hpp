#pragma once
// Levenberg–Marquardt for the small fits of pointing calibration (docs/calibration.md): a beam's
// Gaussian across a scan (5 parameters) and the pointing model over the sky (7 parameters).
// Dense normal equations with a numerical Jacobian are the right tool at these sizes (Press et
// al., Numerical Recipes 3rd ed. §15.5.2; Madsen, Nielsen & Tingleff, "Methods for non-linear
// least squares problems", 2004, §3.2 for the damping update used here).

#include <cstddef>
#include <functional>
#include <vector>

namespace azt::calibration {

/// Fills `residuals` (already sized) for the parameters `p`.
using ResidualFunction =
    std::function<void(const std::vector<double>& p, std::vector<double>& residuals)>;

struct LeastSquaresFit {
  std::vector<double> params;
  /// One standard error per parameter: sqrt(diag((JᵀJ)⁻¹) · χ²/(n − m)); empty when n ≤ m.
  std::vector<double> std_errors;
  /// sqrt(diag((JᵀJ)⁻¹)) per parameter: how much a unit of residual noise moves it. A huge value
  /// says the data barely determine that parameter, even when the residuals happen to be tiny.
  std::vector<double> sensitivities;
  double rms_residual = 0.0;  ///< sqrt(Σr²/n) at the solution
  std::size_t iterations = 0;
  bool converged = false;  ///< the step or the relative change of χ² fell below the tolerance
  bool singular = false;   ///< JᵀJ could not be inverted: some parameter is not determined
};

struct LeastSquaresOptions {
  std::size_t max_iterations = 200;
  double tolerance = 1e-12;  ///< relative change of χ², and step size relative to the parameters
  /// Forward-difference step per parameter (same units as the parameter); empty: 1e-7·max(|p|, 1).
  std::vector<double> steps;
};

/// Minimises Σ r_i(p)² from `start` over `n_residuals` residuals. Never throws; a residual
/// function that returns non-finite values stops the fit at the last good point.
LeastSquaresFit fit_least_squares(const ResidualFunction& residuals, std::vector<double> start,
                                  std::size_t n_residuals, const LeastSquaresOptions& options = {});

/// Solves the symmetric positive system A·x = b by Cholesky (A is n×n, row-major). False when A
/// is not positive definite.
bool solve_symmetric(std::vector<double> a, std::vector<double>& b, std::size_t n);

}  // namespace azt::calibration
