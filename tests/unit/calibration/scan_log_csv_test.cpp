// The scan log as CSV (docs/calibration.md): what the export writes reads back the same; other
// tools' files with fewer columns are read; hostile input is refused with its line and column.
#include "azt/calibration/scan_log_csv.hpp"

#include <gtest/gtest.h>

#include <string>

namespace azt::calibration {
namespace {

ScanLogEntry row(double az, double el, Measured m) {
  ScanLogEntry e;
  e.utc = *astro::parse_iso8601_utc("2025-06-01T16:00:03.250Z");
  e.source = "Cas A";
  e.az_deg = az;
  e.el_deg = el;
  e.daz_deg = 0.8123456;
  e.del_deg = -0.6012345;
  e.measured = m;
  e.sigma_xel_deg = 0.0021;
  e.snr_db = 31.25;
  e.rise_db = 2.1;
  e.beamwidth_deg = 1.6123;
  e.weight = 0.5;
  return e;
}

TEST(ScanLogCsv, WhatIsWrittenReadsBack) {
  const std::vector<ScanLogEntry> log{row(201.5, 45.25, Measured::Az),
                                      row(0.0, 90.0, Measured::El)};
  const std::string text = write_scan_log_csv(log);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "utc,source,az_deg,el_deg,daz_deg,del_deg,weight,measured,sigma_xel_deg,"
            "sigma_el_deg,snr_db,rise_db,beamwidth_deg");
  const auto back = read_scan_log_csv(text);
  ASSERT_TRUE(back) << back.error().message;
  ASSERT_EQ(back->size(), 2U);
  for (std::size_t i = 0; i < log.size(); ++i) {
    const ScanLogEntry& a = log[i];
    const ScanLogEntry& b = (*back)[i];
    EXPECT_NEAR(b.utc.unix_seconds(), a.utc.unix_seconds(), 1e-3);
    EXPECT_EQ(b.source, a.source);
    EXPECT_NEAR(b.az_deg, a.az_deg, 1e-6);
    EXPECT_NEAR(b.el_deg, a.el_deg, 1e-6);
    EXPECT_NEAR(b.daz_deg, a.daz_deg, 1e-6);
    EXPECT_NEAR(b.del_deg, a.del_deg, 1e-6);
    EXPECT_EQ(b.measured, a.measured);
    EXPECT_NEAR(*b.sigma_xel_deg, *a.sigma_xel_deg, 1e-6);
    EXPECT_FALSE(b.sigma_el_deg);
    EXPECT_NEAR(*b.snr_db, *a.snr_db, 0.005);
    EXPECT_NEAR(*b.beamwidth_deg, *a.beamwidth_deg, 1e-4);
    EXPECT_EQ(b.weight, a.weight);
  }
  EXPECT_EQ(write_scan_log_csv(*back), text);
}

TEST(ScanLogCsv, ReadsAnotherToolsColumnsInAnyOrder) {
  const auto log = read_scan_log_csv(
      "# exported by some other program\r\n"
      "\r\n"
      "Source, UTC, Az, El, dAz, dEl, Weight, comment\r\n"
      "sun, 2025-03-14 15:00:00Z, 180.5, 35.0, 0.81, -0.59, 1, clear sky é\r\n"
      "casa,2025-03-14T22:00:00+00:00,45,60,0.7,-0.61,2,\r\n");
  ASSERT_TRUE(log) << log.error().message;
  ASSERT_EQ(log->size(), 2U);
  EXPECT_EQ((*log)[0].source, "sun");
  EXPECT_DOUBLE_EQ((*log)[0].az_deg, 180.5);
  EXPECT_DOUBLE_EQ((*log)[0].daz_deg, 0.81);
  EXPECT_EQ((*log)[0].measured, Measured::Both);
  EXPECT_FALSE((*log)[0].sigma_xel_deg);
  EXPECT_DOUBLE_EQ((*log)[1].weight, 2.0);
  EXPECT_DOUBLE_EQ((*log)[1].del_deg, -0.61);
}

TEST(ScanLogCsv, AHeaderAloneIsAnEmptyLog) {
  const auto log = read_scan_log_csv(scan_log_csv_header() + "\n");
  ASSERT_TRUE(log) << log.error().message;
  EXPECT_TRUE(log->empty());
}

TEST(ScanLogCsv, RefusesHostileInputNamingLineAndColumn) {
  const std::string h = "utc,az,el,daz,del\n";
  const std::string ok = "2025-06-01T00:00:00Z,10,20,0.1,0.2\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"", "no header line: the first line must name the columns"},
      {"# only a comment\n", "no header line"},
      {"utc,az,el,daz\n", "line 1: header: no del_deg column"},
      {"utc,az,el,daz,del,az_deg\n", "line 1: header: az_deg appears twice"},
      {h + ok + "2025-06-01T00:00:00Z,10,20,0.1\n", "line 3: 4 fields, the header has 5"},
      {h + "2025-06-01T00:00:00Z,10,20,0.1,nan\n", "line 2: del_deg: not a number (\"nan\")"},
      {h + "2025-06-01T00:00:00Z,361,20,0.1,0.2\n", "line 2: az_deg: 361 is outside [0, 360]"},
      {h + "2025-06-01T00:00:00Z,10,-1,0.1,0.2\n", "line 2: el_deg: -1 is outside [0, 90]"},
      {h + "2025-06-01T00:00:00Z,10,20,,0.2\n", "line 2: daz_deg: empty"},
      {h + "yesterday,10,20,0.1,0.2\n", "line 2: utc: not an ISO 8601 UTC time"},
      {h + "2025-06-01T00:00:00+02:00,10,20,0.1,0.2\n", "line 2: utc: not an ISO 8601"},
      {h + "\"2025-06-01T00:00:00Z\",10,20,0.1,0.2\n", "line 2: quoted fields are not read"},
      {h + ok + std::string("2025-06-01T00:00:00Z,10,20,0.1,0.2\x01\n"),
       "line 3: a control character"},
      {h + std::string(2000, '1') + "\n", "line 2: longer than 1024 characters"},
      {"utc,az,el,daz,del,measured\n2025-06-01T00:00:00Z,10,20,0.1,0.2,xel\n",
       "line 2: measured: must be both, az or el (\"xel\")"},
      {"utc,az,el,daz,del,source\n2025-06-01T00:00:00Z,10,20,0.1,0.2,sun;rm\n",
       "line 2: source: at most 40 letters"},
      {"utc,az,el,daz,del,weight\n2025-06-01T00:00:00Z,10,20,0.1,0.2,-1\n",
       "line 2: weight: -1 is outside [0, 1e+06]"},
      {"utc,az,el,daz,del,sigma_xel_deg\n2025-06-01T00:00:00Z,10,20,0.1,0.2,0\n",
       "line 2: sigma_xel_deg: 0 is outside (0, 10]"},
  };
  for (const auto& [text, want] : cases) {
    const auto log = read_scan_log_csv(text);
    ASSERT_FALSE(log) << text;
    EXPECT_EQ(log.error().message.rfind(want, 0), 0U) << log.error().message << " for " << text;
  }
}

TEST(ScanLogCsv, RefusesTooManyRows) {
  std::string text = "utc,az,el,daz,del\n";
  for (std::size_t i = 0; i <= kScanLogMaxRows; ++i) text += "2025-06-01T00:00:00Z,1,2,0,0\n";
  const auto log = read_scan_log_csv(text);
  ASSERT_FALSE(log);
  EXPECT_EQ(log.error().message, "line 100002: more than 100000 rows");
}

}  // namespace
}  // namespace azt::calibration
