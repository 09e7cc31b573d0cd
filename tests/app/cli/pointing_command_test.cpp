// `azeltrack pointing fit --csv FILE --json` (docs/calibration.md), run in-process: a scan log of
// 60 offsets made from known terms (0.001° of scatter) fits those terms within 0.005°; too few
// scans are refused with
// the reason; a bad file names its line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "azt/calibration/scan_log_csv.hpp"
#include "cli/commands.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;

calibration::PointingTerms known_terms() {
  calibration::PointingTerms t;
  t.ia_deg = 0.8;
  t.ie_deg = -0.6;
  t.ca_deg = 0.35;
  t.npae_deg = -0.25;
  const calibration::PointingTerms tilt = calibration::tilt_terms(0.5, 120.0);
  t.an_deg = tilt.an_deg;
  t.aw_deg = tilt.aw_deg;
  t.sag_deg = 0.4;
  return t;
}

/// `n` scans across the sky of a mount with `truth`, each offset read with `noise_deg` of scatter
/// (a Sun scan of a 10 m dish at 23 cm: docs/calibration.md).
std::string scan_log(const calibration::PointingTerms& truth, int n, double noise_deg = 0.001) {
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> az(0.0, 360.0), el(10.0, 80.0);
  std::normal_distribution<double> noise(0.0, noise_deg);
  std::vector<calibration::ScanLogEntry> rows;
  for (int i = 0; i < n; ++i) {
    calibration::ScanLogEntry e;
    e.utc = astro::UtcInstant::from_unix_seconds(1748736000.0 + 1200.0 * i);
    e.source = "sun";
    e.az_deg = az(rng);
    e.el_deg = el(rng);
    const auto mount = calibration::mount_for_sky({e.az_deg, e.el_deg}, truth);
    e.daz_deg = std::remainder(mount->az_deg - e.az_deg, 360.0) + noise(rng);
    e.del_deg = mount->el_deg - e.el_deg + noise(rng);
    rows.push_back(e);
  }
  return calibration::write_scan_log_csv(rows);
}

struct CommandRun {
  int status = -1;
  std::string out;
};

/// Runs `azeltrack pointing fit --csv FILE --json` with `csv` as the file.
CommandRun pointing_fit(const std::string& csv) {
  const fs::path path =
      fs::temp_directory_path() / ("azt_pointing_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(path) << csv;
  CLI::App app;
  const Runner run = add_pointing_command(app);
  std::vector<std::string> args{"--json", path.string(), "--csv", "fit", "pointing"};
  app.parse(args);  // CLI11 takes a vector in reverse order
  std::ostringstream out;
  std::streambuf* saved = std::cout.rdbuf(out.rdbuf());
  CommandRun r;
  try {
    r.status = run();
  } catch (...) {
    std::cout.rdbuf(saved);
    fs::remove(path);
    throw;
  }
  std::cout.rdbuf(saved);
  fs::remove(path);
  r.out = out.str();
  return r;
}

TEST(PointingCommand, SixtyOffsetsFromKnownTermsFitThoseTerms) {
  const calibration::PointingTerms truth = known_terms();
  const CommandRun r = pointing_fit(scan_log(truth, 60));
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const auto want = truth.as_array();
  for (std::size_t i = 0; i < want.size(); ++i) {
    const std::string key = calibration::term_key(i);
    EXPECT_NEAR(j["terms"][key].get<double>(), want.at(i), 0.005) << key;
    EXPECT_GT(j["std_errors"][key].get<double>(), 0.0) << key;
    EXPECT_LT(j["std_errors"][key].get<double>(), 0.005) << key;
    EXPECT_LT(std::fabs(j["terms"][key].get<double>() - want.at(i)),
              3.0 * j["std_errors"][key].get<double>())
        << key;  // the standard errors say how far to trust each term
  }
  EXPECT_TRUE(j["held"].empty()) << j["held"];
  EXPECT_GT(j["rms_before_deg"].get<double>(), 0.5);
  EXPECT_LT(j["rms_after_deg"].get<double>(), 0.004);
  EXPECT_EQ(j["residuals"].size(), 60U);
}

TEST(PointingCommand, TooFewScansAreRefusedWithTheReason) {
  const CommandRun r = pointing_fit(scan_log(known_terms(), 2));
  EXPECT_EQ(r.status, kExitFailure);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["refused"], "too few scans to fit: 2, at least 3 needed");
}

TEST(PointingCommand, ABadFileNamesItsLine) {
  try {
    pointing_fit("utc,az,el,daz,del\n2025-06-01T00:00:00Z,10,20,0.1,0.2\n2025-06-01,1,2,3\n");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(": line 3: 4 fields, the header has 5"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace azt::app
