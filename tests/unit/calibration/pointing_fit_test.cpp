// The pointing model fitted to scans across the sky (docs/calibration.md): degree-sized terms come
// back within the noise, and a sky that cannot separate the terms is refused, not fitted.
#include "azt/calibration/pointing_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "azt/calibration/beam_error.hpp"

namespace azt::calibration {
namespace {

PointingTerms random_terms(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> term(-1.0, 1.0);
  std::array<double, PointingTerms::kCount> v{};
  for (double& x : v) x = term(rng);
  return PointingTerms::from_array(v);
}

/// Scans of sources spread over the sky: the mount angles at which the beam was on each source,
/// read with `noise_deg` of scatter per axis.
std::vector<PointingObservation> observe(const PointingTerms& mount_truth, std::mt19937_64& rng,
                                         double noise_deg, int n, double min_el = 10.0,
                                         double max_el = 80.0) {
  std::uniform_real_distribution<double> az(0.0, 360.0), el(min_el, max_el);
  std::normal_distribution<double> noise(0.0, noise_deg);
  std::vector<PointingObservation> out;
  for (int i = 0; i < n; ++i) {
    const control::AzEl sky{az(rng), el(rng)};
    auto mount = mount_for_sky(sky, mount_truth);
    EXPECT_TRUE(mount);
    mount->az_deg += noise(rng);
    mount->el_deg += noise(rng);
    out.push_back({*mount, sky, true, true, {}});
  }
  return out;
}

TEST(PointingFit, RecoversDegreeSizedTermsFromFortyScans) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const PointingTerms truth = random_terms(rng);
    const auto obs = observe(truth, rng, 0.001, 40);
    const auto fit = fit_pointing_model(obs);
    ASSERT_TRUE(fit) << fit.error().message;
    const auto got = fit->terms.as_array(), want = truth.as_array();
    const auto err = fit->std_errors.as_array();
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_NEAR(got.at(i), want.at(i), 0.01) << "term " << i << " trial " << trial;
      EXPECT_NEAR(got.at(i), want.at(i), 5.0 * err.at(i)) << "term " << i << " trial " << trial;
    }
    EXPECT_GT(fit->rms_before_deg, 0.1);
    EXPECT_LT(fit->rms_deg, 0.005);
    EXPECT_LT(beam_error_over_sky(truth, fit->terms).rms_deg, 0.01);
  }
}

TEST(PointingFit, FitsOnlyTheChosenTermsAndHoldsTheRest) {
  std::mt19937_64 rng(5);
  PointingTerms truth;
  truth.ia_deg = 0.4;
  truth.ie_deg = -0.3;
  const auto obs = observe(truth, rng, 0.0, 3);
  PointingTerms start;
  start.sag_deg = 0.05;  // held
  FitOptions only_index;
  only_index.fit = TermMask{};
  only_index.fit[0] = only_index.fit[1] = true;
  const auto fit = fit_pointing_model(obs, start, only_index);
  ASSERT_TRUE(fit) << fit.error().message;
  EXPECT_DOUBLE_EQ(fit->terms.sag_deg, 0.05);
  EXPECT_DOUBLE_EQ(fit->terms.ca_deg, 0.0);
  EXPECT_DOUBLE_EQ(fit->std_errors.sag_deg, 0.0);
  EXPECT_EQ(fit->held[6], "held by request");
  EXPECT_EQ(fit->held[0], "");
  EXPECT_NEAR(fit->terms.ia_deg, 0.4, 0.01);  // the held sag biases IE, not IA
}

TEST(PointingFit, RefusesTooFewScansWithTheReason) {
  std::mt19937_64 rng(1);
  const auto obs = observe(PointingTerms{}, rng, 0.0, 2);
  const auto fit = fit_pointing_model(obs);
  ASSERT_FALSE(fit);
  EXPECT_EQ(fit.error().message, "too few scans to fit: 2, at least 3 needed");
}

TEST(PointingFit, HoldsWhatFewScansCannotDetermine) {
  // Five scans fit at most four terms: the first four of the order (IA, IE, AN, AW) when the
  // scans see them, the rest held at their prior, each saying so.
  std::mt19937_64 rng(7);
  PointingTerms truth;
  truth.ia_deg = 0.3;
  truth.ie_deg = -0.2;
  const auto obs = observe(truth, rng, 0.0, 5);
  const auto fit = fit_pointing_model(obs);
  ASSERT_TRUE(fit) << fit.error().message;
  for (const std::size_t held : {2U, 3U, 6U}) {
    EXPECT_NE(fit->held.at(held).find("too few scans: 5 determine at most 4 terms"),
              std::string::npos)
        << fit->held.at(held);
    EXPECT_EQ(fit->std_errors.as_array().at(held), 0.0);
  }
  EXPECT_NEAR(fit->terms.ia_deg, 0.3, 1e-6);
  EXPECT_NEAR(fit->terms.ie_deg, -0.2, 1e-6);
}

TEST(PointingFit, HoldsTheTermsOneElevationCannotSeparateAndSaysWhy) {
  // Every source at one elevation: IA, CA and NPAE all shift the azimuth alike there, and SAG
  // the elevation as IE does. IA, IE and the tilt are fitted; the rest held, naming the term
  // each resembles and the elevations the scans span.
  std::mt19937_64 rng(2);
  PointingTerms truth;
  truth.ia_deg = 0.5;
  truth.ie_deg = -0.4;
  truth.an_deg = 0.2;
  truth.aw_deg = -0.1;
  const auto obs = observe(truth, rng, 0.001, 30, 40.0, 40.0);
  const auto fit = fit_pointing_model(obs);
  ASSERT_TRUE(fit) << fit.error().message;
  EXPECT_EQ(fit->held[0], "");
  EXPECT_EQ(fit->held[1], "");
  EXPECT_EQ(fit->held[4], "");
  EXPECT_EQ(fit->held[5], "");
  EXPECT_NE(fit->held[2].find("cannot tell it from IA"), std::string::npos) << fit->held[2];
  EXPECT_NE(fit->held[2].find("elevations span 40.0–40.0°"), std::string::npos) << fit->held[2];
  EXPECT_NE(fit->held[3].find("cannot tell it from IA"), std::string::npos) << fit->held[3];
  EXPECT_NE(fit->held[6].find("cannot tell it from IE"), std::string::npos) << fit->held[6];
  EXPECT_NEAR(fit->terms.ia_deg, 0.5, 0.005);
  EXPECT_NEAR(fit->terms.an_deg, 0.2, 0.005);
  EXPECT_LT(fit->rms_deg, 0.003);
}

TEST(PointingFit, ReportsEachObservationsResidualAndLeavesOutWeightZero) {
  std::mt19937_64 rng(11);
  const PointingTerms truth = random_terms(rng);
  auto obs = observe(truth, rng, 0.0, 20);
  obs[3].mount.az_deg += 2.0;  // a wild scan the operator rejected
  obs[3].weight = 0.0;
  const auto fit = fit_pointing_model(obs);
  ASSERT_TRUE(fit) << fit.error().message;
  ASSERT_EQ(fit->residuals.size(), obs.size());
  EXPECT_FALSE(fit->residuals[3].used);
  EXPECT_GT(std::fabs(fit->residuals[3].after.xel_deg), 0.3);  // still shown, far off
  EXPECT_EQ(fit->observations, 19U);
  for (std::size_t i = 0; i < obs.size(); ++i) {
    if (i == 3) continue;
    EXPECT_TRUE(fit->residuals[i].used);
    EXPECT_LT(std::hypot(fit->residuals[i].after.xel_deg, fit->residuals[i].after.el_deg), 1e-5);
    EXPECT_GT(std::hypot(fit->residuals[i].before.xel_deg, fit->residuals[i].before.el_deg), 0.0);
  }
  EXPECT_NEAR(fit->terms.ca_deg, truth.ca_deg, 1e-5);
}

TEST(BeamError, IsZeroForAPerfectModelAndTheErrorsWithoutOne) {
  PointingTerms truth;
  truth.ie_deg = 0.25;
  const BeamError none = beam_error_over_sky(truth, PointingTerms{});
  EXPECT_NEAR(none.rms_deg, 0.25, 1e-9);
  EXPECT_NEAR(none.max_deg, 0.25, 1e-9);
  EXPECT_EQ(none.directions, 24U * 15U);
  EXPECT_LT(beam_error_over_sky(truth, truth).max_deg, 1e-8);
}

}  // namespace
}  // namespace azt::calibration
