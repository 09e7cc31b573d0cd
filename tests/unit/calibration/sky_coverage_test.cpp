// How well scans cover the sky for the pointing model (docs/calibration.md): the expected error
// of the fitted model over the sky per degree of scan noise.
#include "azt/calibration/sky_coverage.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

TEST(TermPartials, MatchTheModelsFirstOrderSums) {
  // A small term's effect on the beam, from the exact model, against the partials.
  const control::AzEl sky{130.0, 35.0};
  const TermPartials p = term_partials(sky);
  for (std::size_t j = 0; j < PointingTerms::kCount; ++j) {
    std::array<double, PointingTerms::kCount> v{};
    v.at(j) = 1e-4;
    const auto mount = mount_for_sky(sky, PointingTerms::from_array(v));
    ASSERT_TRUE(mount);
    // The reading exceeds the beam by the term's effect: mount − sky in tangent-plane units.
    const SkyOffset off = offset_between(sky, *mount);
    EXPECT_NEAR(off.xel_deg / 1e-4, p.xel.at(j), 1e-3) << "term " << j;
    EXPECT_NEAR(off.el_deg / 1e-4, p.el.at(j), 1e-3) << "term " << j;
  }
}

TEST(SkyCoverage, FallsWithScansThatDetermineSomethingNew) {
  SkyCoverage c;
  const double none = c.sky_error();
  c.add({180.0, 40.0});
  const double one = c.sky_error();
  EXPECT_LT(one, none);
  // The same place again helps far less than a new elevation and azimuth.
  EXPECT_LT(c.sky_error_with({60.0, 15.0}), c.sky_error_with({180.0, 40.0}));
  EXPECT_EQ(c.scans(), 1U);
}

TEST(SkyCoverage, SpreadScansBeatScansInOnePlace) {
  SkyCoverage spread, bunched;
  for (int i = 0; i < 24; ++i) {
    spread.add({15.0 * i, 10.0 + 70.0 * (i % 8) / 7.0});
    bunched.add({170.0 + 0.5 * i, 40.0 + 0.2 * i});
  }
  EXPECT_LT(spread.sky_error() * 10.0, bunched.sky_error());
  // 24 well spread scans: the model's error over the sky is a fraction of one scan's noise.
  EXPECT_LT(spread.sky_error(), 1.0);
}

}  // namespace
}  // namespace azt::calibration
