// The scan log's rows (docs/calibration.md): a scan's result turned into the mount's angles on the
// source, one row per line of a cross scan, and rows back into the fit's observations.
#include "azt/calibration/scan_log.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::calibration {
namespace {

control::PositionCorrections corrections_in_use() {
  control::PositionCorrections c;
  c.model.ia_deg = 0.3;
  c.model.ca_deg = -0.2;
  c.model.sag_deg = 0.15;
  c.user = *control::UserCorrections::from_deg(0.12, -0.07);
  std::vector<double> tilt(control::TiltTable::kEntries, 0.0);
  tilt[20] = 0.05;  // 120°
  tilt[21] = 0.08;  // 126°
  c.tilt = *control::TiltTable::make(tilt);
  return c;
}

TEST(ScanLog, MountOnSourceUndoesTheCorrectionsTheStationApplied) {
  // The mount stands at M; the station's corrected reading (the model, the user correction, the
  // tilt table) says the beam is at `believed`; a scan of a source at `sky` finds the offset
  // believed − sky. From that offset, the mount's angles come back.
  const control::PositionCorrections c = corrections_in_use();
  const control::AzEl mount{123.4, 37.5};
  const control::CorrectedPosition believed =
      control::apply_corrections(mount.az_deg, mount.el_deg, c);
  const control::AzEl sky{123.0, 37.9};
  const SkyOffset peak = offset_between(sky, {believed.az_deg, believed.el_deg});
  const control::AzEl back = mount_on_source(c, sky, peak);
  EXPECT_NEAR(back.az_deg, mount.az_deg, 1e-6);
  EXPECT_NEAR(back.el_deg, mount.el_deg, 1e-6);
}

ScanFit a_fit() {
  ScanFit f;
  f.peak = {0.2, -0.1};
  f.peak_std = {0.004, 0.005};
  f.width_xel_deg = 1.7;
  f.width_el_deg = 1.66;
  f.peak_db = 25.0;
  f.noise_db = 0.05;
  return f;
}

TEST(ScanLog, ACrossScanGivesARowPerLineAtItsOwnMoment) {
  FinishedScan s;
  s.source = "sun";
  s.fit = a_fit();
  s.sky_xel = {200.0, 40.0};
  s.sky_el = {201.0, 39.8};
  s.utc_xel = astro::UtcInstant::from_unix_seconds(1748793600.0);
  s.utc_el = astro::UtcInstant::from_unix_seconds(1748793700.0);
  s.source_size_deg = 0.53;
  const auto rows = log_entries(s, control::PositionCorrections{});
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_EQ(rows[0].measured, Measured::Az);
  EXPECT_EQ(rows[1].measured, Measured::El);
  EXPECT_DOUBLE_EQ(rows[0].az_deg, 200.0);
  EXPECT_DOUBLE_EQ(rows[1].el_deg, 39.8);
  EXPECT_NEAR(rows[1].utc.unix_seconds(), 1748793700.0, 1e-3);
  // No corrections: the mount is the source plus the offset found (0.2° of cross-elevation is
  // about 0.2/cos 40° of azimuth).
  const control::AzEl at_xel = apply_offset(s.sky_xel, s.fit.peak);
  EXPECT_NEAR(rows[0].daz_deg, at_xel.az_deg - 200.0, 1e-9);
  EXPECT_NEAR(rows[0].daz_deg, 0.2 / std::cos(40.0 * M_PI / 180.0), 1e-3);
  EXPECT_NEAR(rows[1].del_deg, apply_offset(s.sky_el, s.fit.peak).el_deg - 39.8, 1e-9);
  EXPECT_EQ(rows[0].sigma_xel_deg, 0.004);
  EXPECT_EQ(rows[0].rise_db, 25.0);
  ASSERT_TRUE(rows[0].snr_db);
  EXPECT_NEAR(*rows[0].snr_db,
              10.0 * std::log10((std::pow(10.0, 2.5) - 1.0) / (std::pow(10.0, 0.005) - 1.0)), 1e-9);
  ASSERT_TRUE(rows[0].beamwidth_deg);
  EXPECT_NEAR(*rows[0].beamwidth_deg, std::sqrt(1.68 * 1.68 - 0.53 * 0.53), 1e-9);
}

TEST(ScanLog, AFivePointScanIsOneRowWithoutStandardErrors) {
  FinishedScan s;
  s.source = "casa";
  s.kind = ScanKind::FivePoint;
  s.fit = a_fit();
  s.fit.peak_std = {};
  s.fit.noise_db = 0.0;
  const auto rows = log_entries(s, control::PositionCorrections{});
  ASSERT_EQ(rows.size(), 1U);
  EXPECT_EQ(rows[0].measured, Measured::Both);
  EXPECT_FALSE(rows[0].sigma_xel_deg);
  EXPECT_FALSE(rows[0].snr_db);
}

TEST(ScanLog, RowsBecomeTheFitsObservations) {
  ScanLogEntry e;
  e.az_deg = 100.0;
  e.el_deg = 30.0;
  e.daz_deg = 0.5;
  e.del_deg = -0.25;
  e.measured = Measured::Az;
  e.sigma_xel_deg = 0.01;
  e.weight = 0.5;
  const auto obs = observations_from_log({e});
  ASSERT_EQ(obs.size(), 1U);
  EXPECT_DOUBLE_EQ(obs[0].mount.az_deg, 100.5);
  EXPECT_DOUBLE_EQ(obs[0].mount.el_deg, 29.75);
  EXPECT_TRUE(obs[0].has_xel);
  EXPECT_FALSE(obs[0].has_el);
  EXPECT_DOUBLE_EQ(obs[0].sigma.xel_deg, 0.01);
  EXPECT_DOUBLE_EQ(obs[0].weight, 0.5);
}

TEST(ScanLog, MeasuredNames) {
  EXPECT_EQ(*parse_measured("az"), Measured::Az);
  EXPECT_EQ(to_string(Measured::El), "el");
  EXPECT_FALSE(parse_measured("xel"));
}

}  // namespace
}  // namespace azt::calibration
