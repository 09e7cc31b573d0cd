// Fitting scans (docs/calibration.md): a Gaussian beam on a source, sampled with seeded noise,
// gives back its centre and width; scans with too few readings or no source are refused with the
// reason.
#include "azt/calibration/scan_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace azt::calibration {
namespace {

struct Source {
  double xel_deg = 0.0;
  double el_deg = 0.0;
  double width_deg = 1.0;
  double rise = 3.0;  ///< peak over the baseline, linear (3 = 6 dB)
};

std::vector<ScanSample> measure(const std::vector<ScanPoint>& plan, const Source& s,
                                double noise_db, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_db);
  std::vector<ScanSample> out;
  for (const ScanPoint& p : plan) {
    const double dx = p.offset.xel_deg - s.xel_deg, dy = p.offset.el_deg - s.el_deg;
    const double g =
        std::exp(-4.0 * std::log(2.0) * (dx * dx + dy * dy) / (s.width_deg * s.width_deg));
    out.push_back({p, 10.0 * std::log10(1.0 + s.rise * g) + noise(rng), std::nullopt});
  }
  return out;
}

std::vector<ScanPoint> plan(ScanKind kind, double bw, std::size_t n = 21) {
  ScanSpec spec;
  spec.kind = kind;
  spec.beamwidth_deg = bw;
  spec.points_per_line = n;
  return plan_scan(spec).value();
}

TEST(ScanFit, CrossScanFindsTheOffsetAndWidth) {
  const Source src{0.31, -0.22, 1.2, 3.0};
  const auto fit = fit_scan(ScanKind::Cross, measure(plan(ScanKind::Cross, 1.0), src, 0.0, 1), 1.0);
  ASSERT_TRUE(fit) << fit.error().message;
  EXPECT_NEAR(fit->peak.xel_deg, 0.31, 1e-6);
  EXPECT_NEAR(fit->peak.el_deg, -0.22, 1e-6);
  EXPECT_NEAR(fit->width_xel_deg, 1.2, 1e-6);
  EXPECT_NEAR(fit->width_el_deg, 1.2, 1e-6);
  // The xel line passes 0.22° below the centre: its rise is the Gaussian's there.
  const double rise = 3.0 * std::exp(-4.0 * std::log(2.0) * 0.22 * 0.22 / 1.44);
  EXPECT_NEAR(fit->peak_db, 10.0 * std::log10(1.0 + rise), 1e-6);
  EXPECT_EQ(fit->used, 42U);
  EXPECT_EQ(fit->missing, 0U);
  // The curves the console draws: baseline 1 (linear), flat, the line's rise as amplitude.
  EXPECT_NEAR(fit->xel_curve.baseline, 1.0, 1e-6);
  EXPECT_NEAR(fit->xel_curve.slope, 0.0, 1e-6);
  EXPECT_NEAR(fit->xel_curve.amplitude, rise, 1e-6);
  EXPECT_NEAR(fit->el_curve.amplitude, 3.0 * std::exp(-4.0 * std::log(2.0) * 0.31 * 0.31 / 1.44),
              1e-6);
}

TEST(ScanFit, CrossScanWithTenthDbNoiseIsWithinItsExpectedScatter) {
  // 0.1 dB per reading on a 6 dB source and a 1° beam: over 50 seeds the centre's rms error is
  // a few thousandths of a degree.
  double sum_sq = 0.0;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const Source src{0.1, 0.2, 1.0, 3.0};
    const auto fit =
        fit_scan(ScanKind::Cross, measure(plan(ScanKind::Cross, 1.0, 41), src, 0.1, seed), 1.0);
    ASSERT_TRUE(fit) << fit.error().message;
    sum_sq += std::pow(fit->peak.xel_deg - 0.1, 2) + std::pow(fit->peak.el_deg - 0.2, 2);
    EXPECT_NEAR(fit->noise_db, 0.1, 0.04);
  }
  EXPECT_LT(std::sqrt(sum_sq / 100.0), 0.02);
}

TEST(ScanFit, FivePointAndRasterAgreeWithTheSource) {
  const Source src{0.12, 0.08, 1.0, 5.0};
  const auto five =
      fit_scan(ScanKind::FivePoint, measure(plan(ScanKind::FivePoint, 1.0), src, 0.0, 1), 1.0);
  ASSERT_TRUE(five) << five.error().message;
  EXPECT_NEAR(five->peak.xel_deg, 0.12, 1e-9);
  EXPECT_NEAR(five->peak.el_deg, 0.08, 1e-9);
  EXPECT_NEAR(five->width_xel_deg, 1.0, 1e-9);
  const auto grid =
      fit_scan(ScanKind::Raster, measure(plan(ScanKind::Raster, 1.0, 9), src, 0.0, 1), 1.0);
  ASSERT_TRUE(grid) << grid.error().message;
  EXPECT_NEAR(grid->peak.xel_deg, 0.12, 1e-6);
  EXPECT_NEAR(grid->peak.el_deg, 0.08, 1e-6);
  EXPECT_NEAR(grid->width_el_deg, 1.0, 1e-6);
}

TEST(ScanFit, RefusesAScanWithTooFewGoodReadings) {
  auto samples = measure(plan(ScanKind::Cross, 1.0, 9), Source{}, 0.0, 1);
  // The xel line keeps 5 of its 9, and the el line's centre point lies on it too: 6 of 10.
  for (std::size_t i = 0; i < 4; ++i) samples[i].power_db.reset();
  const auto fit = fit_scan(ScanKind::Cross, samples, 1.0);
  ASSERT_FALSE(fit);
  EXPECT_NE(fit.error().message.find("too few good readings in cross-elevation: 6 of 10"),
            std::string::npos)
      << fit.error().message;
  EXPECT_NE(fit.error().message.find("4 missing"), std::string::npos) << fit.error().message;
}

TEST(ScanFit, RefusesNoiseWithoutASource) {
  const Source none{0.0, 0.0, 1.0, 0.0};
  const auto fit =
      fit_scan(ScanKind::Cross, measure(plan(ScanKind::Cross, 1.0), none, 0.1, 4), 1.0);
  ASSERT_FALSE(fit);
  EXPECT_NE(fit.error().message.find("cross-elevation"), std::string::npos) << fit.error().message;
}

TEST(ScanFit, RefusesASourceOutsideTheScan) {
  const Source far{3.5, 0.0, 1.0, 3.0};  // the scan reaches ±2°
  const auto fit =
      fit_scan(ScanKind::Cross, measure(plan(ScanKind::Cross, 1.0), far, 0.02, 2), 1.0);
  ASSERT_FALSE(fit);
  const auto five =
      fit_scan(ScanKind::FivePoint,
               measure(plan(ScanKind::FivePoint, 1.0), Source{1.6, 0.0, 1.0, 3.0}, 0.0, 1), 1.0);
  ASSERT_FALSE(five);
}

TEST(ScanFit, DeconvolvesTheSourceSize) {
  EXPECT_NEAR(deconvolved_beamwidth_deg(1.0, 0.6), 0.8, 1e-12);
  EXPECT_DOUBLE_EQ(deconvolved_beamwidth_deg(0.5, 0.6), 0.0);
}

}  // namespace
}  // namespace azt::calibration
