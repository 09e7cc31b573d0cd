#include "azt/calibration/least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace azt::calibration {
namespace {

using Matrix = std::vector<double>;  // row-major

double sum_of_squares(const std::vector<double>& r) {
  double s = 0.0;
  for (const double x : r) s += x * x;
  return s;
}

bool all_finite(const std::vector<double>& r) {
  return std::all_of(r.begin(), r.end(), [](double x) { return std::isfinite(x); });
}

double step_for(const LeastSquaresOptions& o, const std::vector<double>& p, std::size_t j) {
  if (j < o.steps.size()) return o.steps[j];
  return 1e-7 * std::max(std::fabs(p[j]), 1.0);
}

/// Forward-difference Jacobian, n × m row-major. False when a residual turns non-finite.
bool jacobian(const ResidualFunction& f, const std::vector<double>& p,
              const std::vector<double>& r0, const LeastSquaresOptions& o, Matrix& jac) {
  const std::size_t n = r0.size(), m = p.size();
  std::vector<double> shifted = p, r(n);
  for (std::size_t j = 0; j < m; ++j) {
    const double h = step_for(o, p, j);
    shifted[j] = p[j] + h;
    f(shifted, r);
    shifted[j] = p[j];
    if (!all_finite(r)) return false;
    for (std::size_t i = 0; i < n; ++i) jac[i * m + j] = (r[i] - r0[i]) / h;
  }
  return true;
}

/// JᵀJ (m × m) and Jᵀr (m).
void normal_equations(const Matrix& jac, const std::vector<double>& r, std::size_t m, Matrix& jtj,
                      std::vector<double>& jtr) {
  const std::size_t n = r.size();
  std::fill(jtj.begin(), jtj.end(), 0.0);
  std::fill(jtr.begin(), jtr.end(), 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t a = 0; a < m; ++a) {
      jtr[a] += jac[i * m + a] * r[i];
      for (std::size_t b = 0; b <= a; ++b) jtj[a * m + b] += jac[i * m + a] * jac[i * m + b];
    }
  }
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = a + 1; b < m; ++b) jtj[a * m + b] = jtj[b * m + a];
  }
}

/// sqrt(diag((JᵀJ)⁻¹)); empty when JᵀJ is singular.
std::vector<double> sensitivities(const Matrix& jtj, std::size_t m) {
  std::vector<double> out(m, 0.0);
  for (std::size_t j = 0; j < m; ++j) {
    std::vector<double> e(m, 0.0);
    e[j] = 1.0;
    if (!solve_symmetric(jtj, e, m)) return {};
    out[j] = std::sqrt(std::max(e[j], 0.0));
  }
  return out;
}

}  // namespace

bool solve_symmetric(std::vector<double> a, std::vector<double>& b, std::size_t n) {
  // Cholesky A = L·Lᵀ in place (lower triangle), then two triangular solves.
  for (std::size_t j = 0; j < n; ++j) {
    double d = a[j * n + j];
    for (std::size_t k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
    if (!(d > 0.0) || !std::isfinite(d)) return false;
    const double l = std::sqrt(d);
    a[j * n + j] = l;
    for (std::size_t i = j + 1; i < n; ++i) {
      double s = a[i * n + j];
      for (std::size_t k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
      a[i * n + j] = s / l;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < i; ++k) b[i] -= a[i * n + k] * b[k];
    b[i] /= a[i * n + i];
  }
  for (std::size_t i = n; i-- > 0;) {
    for (std::size_t k = i + 1; k < n; ++k) b[i] -= a[k * n + i] * b[k];
    b[i] /= a[i * n + i];
  }
  return true;
}

LeastSquaresFit fit_least_squares(const ResidualFunction& residuals, std::vector<double> start,
                                  std::size_t n_residuals, const LeastSquaresOptions& options) {
  const std::size_t m = start.size(), n = n_residuals;
  LeastSquaresFit fit;
  fit.params = std::move(start);
  std::vector<double> r(n), trial_r(n), jtr(m);
  Matrix jac(n * m), jtj(m * m);
  residuals(fit.params, r);
  if (!all_finite(r) || m == 0) {
    fit.singular = m != 0;
    fit.rms_residual =
        std::sqrt(sum_of_squares(r) / static_cast<double>(std::max<std::size_t>(n, 1)));
    return fit;
  }
  double chi2 = sum_of_squares(r), lambda = 1e-3;
  for (; fit.iterations < options.max_iterations && !fit.converged; ++fit.iterations) {
    if (!jacobian(residuals, fit.params, r, options, jac)) break;
    normal_equations(jac, r, m, jtj, jtr);
    bool improved = false;
    while (!improved && lambda < 1e16) {
      Matrix damped = jtj;
      for (std::size_t j = 0; j < m; ++j)
        damped[j * m + j] += lambda * std::max(jtj[j * m + j], 1e-30);
      std::vector<double> step = jtr;
      if (!solve_symmetric(damped, step, m)) {
        lambda *= 10.0;
        continue;
      }
      std::vector<double> trial = fit.params;
      double step_norm = 0.0, param_norm = 0.0;
      for (std::size_t j = 0; j < m; ++j) {
        trial[j] -= step[j];
        step_norm += step[j] * step[j];
        param_norm += fit.params[j] * fit.params[j];
      }
      residuals(trial, trial_r);
      const double trial_chi2 = sum_of_squares(trial_r);
      if (all_finite(trial_r) && trial_chi2 <= chi2) {
        const double change = chi2 - trial_chi2;
        fit.params = std::move(trial);
        std::swap(r, trial_r);
        fit.converged = change <= options.tolerance * std::max(chi2, 1e-300) ||
                        std::sqrt(step_norm) <= options.tolerance * (std::sqrt(param_norm) + 1e-12);
        chi2 = trial_chi2;
        lambda = std::max(lambda / 10.0, 1e-12);
        improved = true;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) {
      fit.converged = true;  // no downhill step at any damping: a minimum to working precision
      break;
    }
  }
  fit.rms_residual = std::sqrt(chi2 / static_cast<double>(n));
  if (jacobian(residuals, fit.params, r, options, jac)) {
    normal_equations(jac, r, m, jtj, jtr);
    fit.sensitivities = sensitivities(jtj, m);
    fit.singular = fit.sensitivities.empty();
    if (!fit.singular && n > m) {
      const double sigma = std::sqrt(chi2 / static_cast<double>(n - m));
      for (const double s : fit.sensitivities) fit.std_errors.push_back(s * sigma);
    }
  }
  return fit;
}

}  // namespace azt::calibration
