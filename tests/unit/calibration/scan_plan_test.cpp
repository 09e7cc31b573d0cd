// The points of cross, five-point and raster scans (docs/calibration.md), and what a plan refuses.
#include "azt/calibration/scan_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

TEST(ScanPlan, CrossScanIsALineInEachAxisThroughTheSource) {
  ScanSpec spec;
  spec.beamwidth_deg = 1.5;
  spec.half_span_beams = 2.0;
  spec.points_per_line = 9;
  const auto plan = plan_scan(spec);
  ASSERT_TRUE(plan);
  ASSERT_EQ(plan->size(), 18U);
  EXPECT_DOUBLE_EQ(plan->front().offset.xel_deg, -3.0);
  EXPECT_DOUBLE_EQ((*plan)[4].offset.xel_deg, 0.0);
  EXPECT_DOUBLE_EQ((*plan)[8].offset.xel_deg, 3.0);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_DOUBLE_EQ((*plan)[i].offset.el_deg, 0.0);
  EXPECT_DOUBLE_EQ((*plan)[9].offset.el_deg, -3.0);
  EXPECT_DOUBLE_EQ(plan->back().offset.el_deg, 3.0);
  EXPECT_DOUBLE_EQ(plan->back().offset.xel_deg, 0.0);
}

TEST(ScanPlan, FivePointHasTheHalfBeamPointsAndTwoReferences) {
  ScanSpec spec;
  spec.kind = ScanKind::FivePoint;
  spec.beamwidth_deg = 2.0;
  const auto plan = plan_scan(spec);
  ASSERT_TRUE(plan);
  ASSERT_EQ(plan->size(), 7U);
  int references = 0;
  for (const ScanPoint& p : *plan) {
    if (p.reference) {
      ++references;
      EXPECT_DOUBLE_EQ(std::fabs(p.offset.xel_deg), 8.0);
    } else {
      EXPECT_LE(std::fabs(p.offset.xel_deg) + std::fabs(p.offset.el_deg), 1.0);
    }
  }
  EXPECT_EQ(references, 2);
}

TEST(ScanPlan, RasterSweepsRowsBackAndForth) {
  ScanSpec spec;
  spec.kind = ScanKind::Raster;
  spec.points_per_line = 5;
  const auto plan = plan_scan(spec);
  ASSERT_TRUE(plan);
  ASSERT_EQ(plan->size(), 25U);
  EXPECT_DOUBLE_EQ((*plan)[4].offset.xel_deg, 2.0);  // row 0 ends on the right
  EXPECT_DOUBLE_EQ((*plan)[5].offset.xel_deg, 2.0);  // row 1 starts there
  EXPECT_DOUBLE_EQ((*plan)[5].offset.el_deg, -1.0);
  EXPECT_DOUBLE_EQ((*plan)[9].offset.xel_deg, -2.0);
}

TEST(ScanPlan, RefusesNamingTheField) {
  ScanSpec spec;
  spec.beamwidth_deg = 0.0;
  EXPECT_NE(plan_scan(spec).error().message.find("beamwidth_deg"), std::string::npos);
  spec.beamwidth_deg = 1.0;
  spec.points_per_line = 8;
  EXPECT_NE(plan_scan(spec).error().message.find("points_per_line"), std::string::npos);
  spec.points_per_line = 103;
  EXPECT_FALSE(plan_scan(spec));
  spec.points_per_line = 9;
  spec.half_span_beams = 0.0;
  EXPECT_NE(plan_scan(spec).error().message.find("half_span_beams"), std::string::npos);
  spec.kind = ScanKind::FivePoint;
  spec.reference_beams = 1.0;
  EXPECT_NE(plan_scan(spec).error().message.find("reference_beams"), std::string::npos);
}

TEST(ScanPlan, KindsParseAndPrint) {
  for (const ScanKind k : {ScanKind::Cross, ScanKind::FivePoint, ScanKind::Raster}) {
    EXPECT_EQ(*parse_scan_kind(to_string(k)), k);
  }
  EXPECT_FALSE(parse_scan_kind("spiral"));
}

}  // namespace
}  // namespace azt::calibration
