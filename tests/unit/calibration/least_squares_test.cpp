// Levenberg–Marquardt and the Cholesky solver behind the calibration fits (docs/calibration.md).
#include "azt/calibration/least_squares.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace azt::calibration {
namespace {

TEST(SolveSymmetric, SolvesAPositiveSystemAndRefusesASingularOne) {
  // [4 2; 2 3]·x = [2; 1] has x = [0.5; 0].
  std::vector<double> b{2.0, 1.0};
  ASSERT_TRUE(solve_symmetric({4.0, 2.0, 2.0, 3.0}, b, 2));
  EXPECT_NEAR(b[0], 0.5, 1e-15);
  EXPECT_NEAR(b[1], 0.0, 1e-15);
  std::vector<double> c{1.0, 1.0};
  EXPECT_FALSE(solve_symmetric({1.0, 1.0, 1.0, 1.0}, c, 2));
}

TEST(LeastSquares, RecoversAnExponentialDecayFromNoisyData) {
  // y = 3·exp(−0.7·t) + 0.5 with seeded noise of 0.01: the fit lands within a few standard
  // errors, and the standard errors are of the size the noise implies.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<double> t, y;
  for (int i = 0; i < 60; ++i) {
    t.push_back(0.1 * i);
    y.push_back(3.0 * std::exp(-0.7 * t.back()) + 0.5 + noise(rng));
  }
  const ResidualFunction f = [&](const std::vector<double>& p, std::vector<double>& r) {
    for (std::size_t i = 0; i < t.size(); ++i) r[i] = p[0] * std::exp(-p[1] * t[i]) + p[2] - y[i];
  };
  const LeastSquaresFit fit = fit_least_squares(f, {1.0, 0.1, 0.0}, t.size());
  ASSERT_TRUE(fit.converged);
  ASSERT_EQ(fit.std_errors.size(), 3U);
  const double truth[] = {3.0, 0.7, 0.5};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(fit.params[i], truth[i], 4.0 * fit.std_errors[i]) << i;
    EXPECT_GT(fit.std_errors[i], 0.0);
    EXPECT_LT(fit.std_errors[i], 0.05);
  }
  EXPECT_NEAR(fit.rms_residual, 0.01, 0.003);
}

TEST(LeastSquares, FlagsAParameterTheDataDoNotDetermine) {
  // p[0] and p[1] enter only as their sum: JᵀJ is singular.
  const ResidualFunction f = [](const std::vector<double>& p, std::vector<double>& r) {
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = p[0] + p[1] - static_cast<double>(i % 3);
  };
  const LeastSquaresFit fit = fit_least_squares(f, {0.0, 0.0}, 9);
  EXPECT_TRUE(fit.singular);
}

TEST(LeastSquares, StopsOnAResidualFunctionThatTurnsNonFinite) {
  const ResidualFunction f = [](const std::vector<double>& p, std::vector<double>& r) {
    for (double& x : r) x = std::log(p[0]);  // NaN below 0
  };
  const LeastSquaresFit fit = fit_least_squares(f, {-1.0}, 3);
  EXPECT_FALSE(fit.converged);
}

}  // namespace
}  // namespace azt::calibration
