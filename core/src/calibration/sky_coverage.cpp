#include "azt/calibration/sky_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "azt/calibration/least_squares.hpp"

namespace azt::calibration {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

}  // namespace

TermPartials term_partials(const control::AzEl& sky) {
  // pointing_model.hpp's sums, the azimuth ones times cos E (cross-elevation): IA·cos E, −CA,
  // +NPAE·sin E, +AN·sin A·sin E, −AW·cos A·sin E; elevation IE, AN·cos A, AW·sin A, SAG·cos E.
  const double a = sky.az_deg * kDegToRad, e = sky.el_deg * kDegToRad;
  TermPartials p;
  p.xel = {
      std::cos(e), 0.0, -1.0, std::sin(e), std::sin(a) * std::sin(e), -std::cos(a) * std::sin(e),
      0.0};
  p.el = {0.0, 1.0, 0.0, 0.0, std::cos(a), std::sin(a), std::cos(e)};
  return p;
}

SkyCoverage::SkyCoverage(double min_el_deg, double max_el_deg) {
  double directions = 0.0;
  for (int az_step = 0; az_step < 24; ++az_step) {
    for (int el_step = 0; min_el_deg + 5.0 * el_step <= max_el_deg + 1e-9; ++el_step) {
      accumulate(sky_moments_, {15.0 * az_step, min_el_deg + 5.0 * el_step}, 1.0);
      directions += 1.0;
    }
  }
  if (directions > 0.0) {
    for (double& m : sky_moments_) m /= directions;
  }
  for (std::size_t j = 0; j < kTerms; ++j) normal_[j * kTerms + j] = kPrior;
}

void SkyCoverage::accumulate(Matrix& normal, const control::AzEl& sky, double weight, bool xel,
                             bool el) {
  const TermPartials p = term_partials(sky);
  const double wx = xel ? weight : 0.0, we = el ? weight : 0.0;
  for (std::size_t a = 0; a < kTerms; ++a) {
    for (std::size_t b = 0; b < kTerms; ++b) {
      normal[a * kTerms + b] += wx * p.xel[a] * p.xel[b] + we * p.el[a] * p.el[b];
    }
  }
}

void SkyCoverage::add(const control::AzEl& sky, double weight, bool xel, bool el) {
  accumulate(normal_, sky, weight, xel, el);
  offsets_ += (xel ? 1U : 0U) + (el ? 1U : 0U);
}

double SkyCoverage::error_of(const Matrix& normal) const {
  // trace(N⁻¹·M): column j of N⁻¹ by one solve each (7×7, Cholesky).
  const std::vector<double> n(normal.begin(), normal.end());
  double trace = 0.0;
  for (std::size_t j = 0; j < kTerms; ++j) {
    std::vector<double> column(kTerms, 0.0);
    column[j] = 1.0;
    if (!solve_symmetric(n, column, kTerms)) return std::sqrt(1.0 / kPrior);
    for (std::size_t i = 0; i < kTerms; ++i) trace += column[i] * sky_moments_[i * kTerms + j];
  }
  return std::sqrt(std::max(trace, 0.0));
}

double SkyCoverage::sky_error() const { return error_of(normal_); }

double SkyCoverage::sky_error_with(const control::AzEl& sky, double weight) const {
  Matrix n = normal_;
  accumulate(n, sky, weight);
  return error_of(n);
}

}  // namespace azt::calibration
