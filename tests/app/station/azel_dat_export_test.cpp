// azel.dat every second (docs/eme.md): the Moon and Sun as the sky engine sees them, the echo
// Doppler at the band and its rate from one second to the next, the tracked source, R/T, the
// optional fifth line; and a failed write said once, not every second.
#include "station/azel_dat_export.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "azt/astro/erfa_ephemeris.hpp"
#include "common/sky_report.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

constexpr double kAt = 1741910400.0;  // 2025-03-14 00:00 UTC

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string f; std::getline(s, f, ',');) out.push_back(f);
  return out;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string l; std::getline(s, l);) out.push_back(l);
  return out;
}

class AzelDatTest : public ::testing::Test {
 protected:
  AzelDatExport& exporter() {
    exporter_.emplace(
        io_, AzelDatParts{"/x/azel.dat", ephemeris_, sky_, [this] { return now_; },
                          [this] { return source_; }, [this] { return tx_; }, run_inline,
                          [this](const std::string& path, const std::string& text) -> Result<bool> {
                            writes_.push_back(path + "|" + text);
                            if (!write_ok_) return fail("Permission denied");
                            return true;
                          },
                          [this](const std::string& l) { log_.push_back(l); }, pol_line_});
    return *exporter_;
  }

  boost::asio::io_context io_;
  astro::ErfaEphemeris ephemeris_;
  SkyConfig sky_ = sky_config_from(ConfigFile::parse(
      "[station]\ngrid = \"FN06HE\"\n[sky]\nband = \"1296\"\ndx_grid = \"QF56OD\"\n", "t.toml"));
  double now_ = kAt;
  std::optional<astro::Target> source_;
  bool tx_ = false;
  bool write_ok_ = true;
  bool pol_line_ = false;
  std::vector<std::string> writes_;
  std::vector<std::string> log_;
  std::optional<AzelDatExport> exporter_;
};

TEST_F(AzelDatTest, TheSkyEnginesNumbersInWsjtxsFormat) {
  AzelDatExport& e = exporter();
  ASSERT_EQ(writes_.size(), 1U) << "written at once";
  const auto text = e.text_at(kAt + 60.0);
  ASSERT_TRUE(text.has_value());
  const auto l = lines(*text);
  ASSERT_EQ(l.size(), 4U);
  const auto sky =
      sky_snapshot(ephemeris_, sky_.settings, astro::UtcInstant::from_unix_seconds(kAt + 60.0));
  const auto moon = sky->observe(astro::Target::moon());
  char expected[64];
  std::snprintf(expected, sizeof expected, "00:01:00,%5.1f,%5.1f,Moon",
                moon->observation.place.az_deg, moon->observation.el_deg);
  EXPECT_EQ(l[0], expected);
  EXPECT_EQ(fields(l[1]).back(), "Sun");
  EXPECT_EQ(l[2], "00:01:00,  0.0,  0.0,Source") << "no source tracked";
  const auto d = fields(l[3]);
  ASSERT_EQ(d.size(), 7U);  // "…,Doppler, R": the last comma is WSJT-X's too
  EXPECT_EQ(d[0], " 1296");
  const double self_hz = astro::self_echo_doppler_hz(*sky_.settings.freq_mhz,
                                                     *moon->observation.place.range_rate_km_s);
  EXPECT_NEAR(std::stod(d[3]), self_hz, 0.51);
  EXPECT_NEAR(
      std::stod(d[1]),
      astro::dx_echo_doppler_hz(*sky_.settings.freq_mhz, *moon->observation.place.range_rate_km_s,
                                *moon->dx_range_rate_km_s),
      0.51);
  // The rate over the minute from the first write: the Doppler's change, per minute.
  const auto first = fields(lines(writes_[0].substr(writes_[0].find('|') + 1))[3]);
  EXPECT_NEAR(std::stod(d[4]), std::stod(d[3]) - std::stod(first[3]), 1.0);
  EXPECT_EQ(d[5] + "," + d[6], "Doppler, R");
}

TEST_F(AzelDatTest, TheTrackedSourceAndTransmit) {
  source_ = astro::Target::radec(83.633, 22.014).value();  // Taurus A
  tx_ = true;
  const auto l = lines(*exporter().text_at(kAt));
  EXPECT_NE(l[2], "00:00:00,  0.0,  0.0,Source");
  EXPECT_EQ(fields(l[3]).back(), " T");
}

TEST_F(AzelDatTest, TheFifthLineHasTheMoonConditionsOfTheSameInstant) {
  pol_line_ = true;
  const auto l = lines(*exporter().text_at(kAt));
  ASSERT_EQ(l.size(), 5U);
  const auto p = fields(l[4]);
  ASSERT_EQ(p.size(), 6U);
  EXPECT_EQ(p[5], "Pol");
  const auto sky =
      sky_snapshot(ephemeris_, sky_.settings, astro::UtcInstant::from_unix_seconds(kAt));
  const auto moon = sky->observe(astro::Target::moon());
  const auto c = moon_conditions_at(*moon, *sky, sky_.settings);
  ASSERT_TRUE(c && c->dx_dpol_deg && c->mnr_db && c->width_hz && c->dx_width_hz);
  EXPECT_NEAR(std::stod(p[0]), *c->dx_dpol_deg, 0.051) << "Dpol between the stations";
  EXPECT_NEAR(std::stod(p[1]), *c->mnr_db, 0.051);
  EXPECT_NEAR(std::stod(p[2]), c->dgrd_db, 0.051);
  EXPECT_NEAR(std::stod(p[3]), *c->width_hz, 0.051);
  EXPECT_NEAR(std::stod(p[4]), *c->dx_width_hz, 0.051);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(p[i].size(), 8U) << "f8.1: " << p[i];
}

TEST_F(AzelDatTest, AFailedWriteIsSaidOnceAndItsRecoveryOnce) {
  write_ok_ = false;
  AzelDatExport& e = exporter();
  e.write_now();
  e.write_now();
  ASSERT_EQ(log_.size(), 1U);
  EXPECT_EQ(log_[0], "azel.dat: not written: Permission denied");
  write_ok_ = true;
  e.write_now();
  e.write_now();
  ASSERT_EQ(log_.size(), 2U);
  EXPECT_EQ(log_[1], "azel.dat: writing /x/azel.dat");
  EXPECT_EQ(writes_.size(), 5U);
}

}  // namespace
}  // namespace azt::app
