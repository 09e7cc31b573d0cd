// The fit as the program prints it (docs/calibration.md): the terms in [pointing]'s key names,
// the held ones with their reasons, one residual per log row beside the row.
#include "calibration/fit_report.hpp"

#include <gtest/gtest.h>

namespace azt::app {
namespace {

std::vector<calibration::ScanLogEntry> rows_at_one_elevation() {
  calibration::PointingTerms truth;
  truth.ia_deg = 0.3;
  std::vector<calibration::ScanLogEntry> rows;
  for (int i = 0; i < 12; ++i) {
    calibration::ScanLogEntry e;
    e.utc = astro::UtcInstant::from_unix_seconds(1748793600.0 + 600.0 * i);
    e.source = i % 2 == 0 ? "sun" : "casa";
    e.az_deg = 30.0 * i;
    e.el_deg = 35.0;
    const auto mount = calibration::mount_for_sky({e.az_deg, e.el_deg}, truth);
    e.daz_deg = std::remainder(mount->az_deg - e.az_deg, 360.0);
    e.del_deg = mount->el_deg - e.el_deg;
    rows.push_back(e);
  }
  return rows;
}

TEST(FitReport, TermsHeldTermsAndEachRowsResidual) {
  const auto rows = rows_at_one_elevation();
  const auto fit = calibration::fit_pointing_model(calibration::observations_from_log(rows));
  ASSERT_TRUE(fit) << fit.error().message;
  const nlohmann::json j = fit_json(*fit, rows);
  EXPECT_NEAR(j["terms"]["ia_deg"].get<double>(), 0.3, 1e-6);
  EXPECT_EQ(j["terms"].size(), 7U);
  EXPECT_EQ(j["std_errors"].size(), 7U);
  EXPECT_GT(j["rms_before_deg"].get<double>(), 0.2);
  EXPECT_LT(j["rms_after_deg"].get<double>(), 1e-6);
  EXPECT_EQ(j["scans"], 12);
  // One elevation: collimation, sag and the non-perpendicularity are held, each with its reason.
  ASSERT_TRUE(j["held"].contains("ca_deg"));
  EXPECT_NE(j["held"]["ca_deg"].get<std::string>().find("cannot tell it from IA"),
            std::string::npos);
  EXPECT_TRUE(j["held"].contains("sag_deg"));
  EXPECT_TRUE(j["held"].contains("npae_deg"));
  EXPECT_FALSE(j["held"].contains("ia_deg"));
  ASSERT_EQ(j["residuals"].size(), rows.size());
  const nlohmann::json& r = j["residuals"][3];
  EXPECT_EQ(r["source"], "casa");
  EXPECT_EQ(r["utc"], "2025-06-01T16:30:00.000Z");
  EXPECT_EQ(r["az_deg"], 90.0);
  EXPECT_EQ(r["measured"], "both");
  EXPECT_TRUE(r["used"].get<bool>());
  // The beam is IA west of where the reading says: it stands +IA·cos E from the source.
  EXPECT_NEAR(r["xel_before_deg"].get<double>(), 0.3 * std::cos(35.0 * M_PI / 180.0), 1e-3);
  EXPECT_LT(std::fabs(r["xel_after_deg"].get<double>()), 1e-6);
}

}  // namespace
}  // namespace azt::app
