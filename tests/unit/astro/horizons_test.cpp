#include "azt/astro/horizons.hpp"

#include <erfa.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

// Fixtures: tests/data/horizons/make_fixtures.py (Horizons layout, ERFA's Moon for the vectors,
// a synthetic north-crossing track for the observer table).

namespace azt::astro {
namespace {

constexpr double kMetresPerAu = 149597870700.0;
constexpr double kAuKm = 149597870.7;
constexpr double kSecondsPerDay = 86400.0;
constexpr double kStartJd = 2460735.5;  // 2025-Mar-01 00:00 (TDB in the vector tables)

std::string fixture(const std::string& name) {
  std::ifstream in(std::string(AZT_TEST_DATA_DIR) + "/horizons/" + name);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_FALSE(text.str().empty()) << name;
  return text.str();
}

/// `text` with the first `from` replaced by `to` (the test fails if `from` is absent).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

PosVel moon98(double jd1, double jd2) {
  double pv[2][3];
  eraMoon98(jd1, jd2, pv);
  return PosVel{{pv[0][0], pv[0][1], pv[0][2]}, {pv[1][0], pv[1][1], pv[1][2]}};
}

double distance_m(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) * kMetresPerAu;
}

/// The first row after $$SOE of a CSV vector table: X, Y, Z (km) and VX, VY, VZ (km/s), as
/// written (the PosVel's fields hold the raw km and km/s here).
PosVel first_row_km(const std::string& text) {
  std::istringstream in(text.substr(text.find("$$SOE") + 5));
  std::string line;
  while (std::getline(in, line) && line.find(',') == std::string::npos) {
  }
  std::istringstream fields(line);
  std::string field;
  std::vector<double> v;
  for (int i = 0; std::getline(fields, field, ','); ++i) {
    if (i >= 2 && i < 8) v.push_back(std::stod(field));
  }
  EXPECT_EQ(v.size(), 6U) << line;
  v.resize(6, 0.0);
  return PosVel{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
}

std::string vectors_error(const std::string& text) {
  auto table = SpacecraftTable::parse_horizons_vectors(text);
  EXPECT_FALSE(table.ok());
  return table.ok() ? std::string() : table.error().message;
}

TEST(HorizonsVectors, CsvKmSIsReadAndConvertedToAuAndAuPerDay) {
  auto table = SpacecraftTable::parse_horizons_vectors(fixture("moon_vectors_csv_kms.txt"));
  ASSERT_TRUE(table.ok()) << table.error().message;
  EXPECT_EQ(table->target(), "Moon (301)");
  ASSERT_EQ(table->nodes().size(), 145U);
  const auto& first = table->nodes().front();
  EXPECT_EQ(first.tdb.total(), kStartJd);
  // The first row's own km and km/s, read here: the conversion to au and au/day is exact to
  // ~1e-16 relative. (Not against eraMoon98 recomputed here: ERFA built for arm64 fuses
  // multiply-adds, and its Moon differs from the x86-64 build's that wrote the file by 1e-13.)
  const PosVel row = first_row_km(fixture("moon_vectors_csv_kms.txt"));
  const double km_per_au = kMetresPerAu / 1000.0;
  const Vec3 pos_au{row.pos_au[0] / km_per_au, row.pos_au[1] / km_per_au,
                    row.pos_au[2] / km_per_au};
  const double s_per_d = kSecondsPerDay;
  const Vec3 vel_au_d{row.vel_au_d[0] * s_per_d / km_per_au, row.vel_au_d[1] * s_per_d / km_per_au,
                      row.vel_au_d[2] * s_per_d / km_per_au};
  EXPECT_LT(distance_m(first.state.pos_au, pos_au), 1e-6);
  EXPECT_LT(distance_m(first.state.vel_au_d, vel_au_d) / kSecondsPerDay, 1e-9);
  // And the file is the Moon: eraMoon98 here agrees to well within a metre.
  EXPECT_LT(distance_m(first.state.pos_au, moon98(kStartJd, 0.0).pos_au), 1e-3);
}

TEST(HorizonsVectors, TextAuDTableAgreesWithTheCsvKmSTable) {
  auto csv = SpacecraftTable::parse_horizons_vectors(fixture("moon_vectors_csv_kms.txt"));
  auto text = SpacecraftTable::parse_horizons_vectors(fixture("moon_vectors_text_aud.txt"));
  ASSERT_TRUE(csv.ok()) << csv.error().message;
  ASSERT_TRUE(text.ok()) << text.error().message;
  ASSERT_EQ(text->nodes().size(), 7U);
  for (std::size_t k = 0; k < 7; ++k) {
    const auto& hourly = text->nodes()[k];
    const auto& ten_minute = csv->nodes()[6 * k];
    EXPECT_NEAR(hourly.tdb.total(), ten_minute.tdb.total(), 1e-9);
    EXPECT_LT(distance_m(hourly.state.pos_au, ten_minute.state.pos_au), 1e-6) << k;
    EXPECT_LT(distance_m(hourly.state.vel_au_d, ten_minute.state.vel_au_d) / kSecondsPerDay, 1e-9)
        << k;
  }
}

// The bound is eraMoon98's own inconsistency: its velocity differs from the derivative of its
// position by ~5 mm/s, 0.2 m over a 10-minute Hermite step (see tabulated_ephemeris.hpp).
TEST(HorizonsVectors, HermiteMidpointsFollowMoon98WithinAMetre) {
  auto table = SpacecraftTable::parse_horizons_vectors(fixture("moon_vectors_csv_kms.txt"));
  ASSERT_TRUE(table.ok()) << table.error().message;
  double worst_m = 0.0, worst_m_s = 0.0;
  for (int k = 0; k < 144; ++k) {
    const double jd2 = (k + 0.5) / 144.0;
    auto got = table->at(JulianDate{kStartJd, jd2});
    ASSERT_TRUE(got.ok()) << got.error().message;
    const PosVel want = moon98(kStartJd, jd2);
    worst_m = std::max(worst_m, distance_m(got->pos_au, want.pos_au));
    worst_m_s = std::max(worst_m_s, distance_m(got->vel_au_d, want.vel_au_d) / kSecondsPerDay);
  }
  EXPECT_LT(worst_m, 1.0);
  EXPECT_LT(worst_m_s, 0.01);
}

TEST(HorizonsVectors, UnevenSpacingIsInterpolatedOverTheLongerGap) {
  // Drop the 00:10 record: 00:00 and 00:20 then bracket 00:15.
  std::string text = fixture("moon_vectors_csv_kms.txt");
  const auto start = text.find("2460735.506944444");
  text.erase(start, text.find('\n', start) + 1 - start);
  auto table = SpacecraftTable::parse_horizons_vectors(text);
  ASSERT_TRUE(table.ok()) << table.error().message;
  ASSERT_EQ(table->nodes().size(), 144U);
  const double jd2 = 15.0 / 1440.0;
  auto got = table->at(JulianDate{kStartJd, jd2});
  ASSERT_TRUE(got.ok()) << got.error().message;
  EXPECT_LT(distance_m(got->pos_au, moon98(kStartJd, jd2).pos_au), 4.0);
}

TEST(HorizonsVectors, OutsideTheSpanIsAnErrorNamingIt) {
  auto table = SpacecraftTable::parse_horizons_vectors(fixture("moon_vectors_csv_kms.txt"));
  ASSERT_TRUE(table.ok()) << table.error().message;
  EXPECT_TRUE(table->at(JulianDate{kStartJd, 1.0}).ok());  // the last node itself
  for (double jd2 : {-1e-6, 1.0 + 1e-6, std::nan("")}) {
    auto got = table->at(JulianDate{kStartJd, jd2});
    ASSERT_FALSE(got.ok()) << jd2;
    EXPECT_TRUE(test::contains(got.error().message, "covers TDB JD 2460735.5 .. 2460736.5"))
        << got.error().message;
    EXPECT_TRUE(test::contains(got.error().message, "Moon (301)")) << got.error().message;
  }
}

TEST(HorizonsVectors, EclipticFrameIsRefusedNamingTheLine) {
  const std::string text = fixture("moon_vectors_csv_kms.txt");
  const std::string modern = vectors_error(
      replaced(text, "Reference frame : ICRF", "Reference frame : Ecliptic of J2000.0"));
  EXPECT_TRUE(test::contains(modern, "line 28 (Reference frame : Ecliptic of J2000.0)")) << modern;
  EXPECT_TRUE(test::contains(modern, "REF_PLANE='FRAME'")) << modern;
  // Older replies: "ICRF/J2000.0" with the plane on its own line.
  const std::string old = vectors_error(
      replaced(text, "Reference frame : ICRF",
               "Reference frame : ICRF/J2000.0\nCoordinate systm: Ecliptic and Mean Equinox of "
               "Reference Epoch"));
  EXPECT_TRUE(test::contains(old, "line 29 (Coordinate systm: Ecliptic")) << old;
  EXPECT_TRUE(SpacecraftTable::parse_horizons_vectors(
                  replaced(text, "Reference frame : ICRF",
                           "Reference frame : ICRF/J2000.0\nCoordinate systm: Earth Mean Equator "
                           "and Equinox of Reference Epoch"))
                  .ok());
}

TEST(HorizonsVectors, OtherCentresAndCorrectedStatesAreRefused) {
  const std::string text = fixture("moon_vectors_csv_kms.txt");
  const std::string sun =
      vectors_error(replaced(text, "Center body name: Earth (399)", "Center body name: Sun (10)"));
  EXPECT_TRUE(test::contains(sun, "line 14 (Center body name: Sun (10)")) << sun;
  EXPECT_TRUE(test::contains(sun, "500@399")) << sun;
  const std::string site =
      vectors_error(replaced(text, "Center-site name: BODY CENTER", "Center-site name: Goldstone"));
  EXPECT_TRUE(test::contains(site, "line 15")) << site;
  const std::string corrected =
      vectors_error(replaced(text, "GEOMETRIC cartesian states", "ASTROMETRIC cartesian states"));
  EXPECT_TRUE(test::contains(corrected, "VEC_CORR='NONE'")) << corrected;
  const std::string units =
      vectors_error(replaced(text, "Output units    : KM-S", "Output units    : AU-S"));
  EXPECT_TRUE(test::contains(units, "line 24 (Output units    : AU-S)")) << units;
}

TEST(HorizonsVectors, MissingMarkersBadNumbersAndDisorderAreNamed) {
  const std::string text = fixture("moon_vectors_csv_kms.txt");
  EXPECT_TRUE(test::contains(vectors_error(replaced(text, "$$SOE", "")), "no $$SOE"));
  EXPECT_TRUE(test::contains(vectors_error(replaced(text, "$$EOE", "")), "no $$EOE"));
  const std::string bad =
      vectors_error(replaced(text, " 3.603567481252891E+05", " 3.6035674812528x1E+05"));
  EXPECT_TRUE(test::contains(bad, "line 34 (2460735.506944444, A.D. 2025-Mar-01 00:10")) << bad;
  EXPECT_TRUE(test::contains(bad, "\"3.6035674812528x1E+05\" in column X")) << bad;
  const std::string text_bad =
      vectors_error(replaced(fixture("moon_vectors_text_aud.txt"), "VY= 5.477450574003106E-04",
                             "VY= 5.477450574003106E-0q"));
  EXPECT_TRUE(test::contains(text_bad, "line 37")) << text_bad;
  const std::string disorder =
      vectors_error(replaced(text, "2460735.513888889,", "2460735.500000000,"));
  EXPECT_TRUE(test::contains(disorder, "line 35")) << disorder;
  EXPECT_TRUE(test::contains(disorder, "not after the previous")) << disorder;
  const std::string ut = vectors_error(replaced(text, "  JDTDB,", "   JDUT,"));
  EXPECT_TRUE(test::contains(ut, "TIME_TYPE='TDB'")) << ut;
}

std::string observer_error(const std::string& text) {
  auto table = ObserverTable::parse_horizons_observer(text);
  EXPECT_FALSE(table.ok());
  return table.ok() ? std::string() : table.error().message;
}

TEST(HorizonsObserver, SiteAndRowsAreRead) {
  auto table = ObserverTable::parse_horizons_observer(fixture("observer_north.txt"));
  ASSERT_TRUE(table.ok()) << table.error().message;
  EXPECT_EQ(table->target(), "Synthetic probe (-999)");
  EXPECT_EQ(table->size(), 13U);
  EXPECT_NEAR(table->site().lon_east_deg, 350.1234 - 360.0, 1e-12);
  EXPECT_NEAR(table->site().lat_deg, 48.7654, 1e-12);
  EXPECT_NEAR(table->site().alt_km, 0.312, 1e-12);
  auto row = table->at(test::calendar(2025, 3, 1, 0, 0, 0.0));
  ASSERT_TRUE(row.ok()) << row.error().message;
  EXPECT_NEAR(row->az_deg, 354.0, 1e-9);
  EXPECT_NEAR(row->el_deg, 20.0, 1e-9);
  EXPECT_NEAR(row->range_km, 2.5e6, 0.01);  // 14 decimals of au: 1.5 m
  EXPECT_NEAR(row->range_rate_km_s, -1.5, 1e-9);
}

TEST(HorizonsObserver, AzimuthIsInterpolatedAcrossNorth) {
  auto table = ObserverTable::parse_horizons_observer(fixture("observer_north.txt"));
  ASSERT_TRUE(table.ok()) << table.error().message;
  // The track sweeps 1 deg per 10 minutes through north at 01:00.
  for (const auto& [minute, az] :
       {std::pair{55, 359.5}, std::pair{60, 0.0}, std::pair{65, 0.5}, std::pair{58, 359.8},
        std::pair{5, 354.5}, std::pair{115, 5.5}}) {
    auto look = table->at(test::calendar(2025, 3, 1, minute / 60, minute % 60, 0.0));
    ASSERT_TRUE(look.ok()) << look.error().message;
    // Compared modulo 360: at 01:00 the row time's rounding puts the answer a hair below 360.
    EXPECT_NEAR(std::remainder(look->az_deg - az, 360.0), 0.0, 1e-6) << minute;
    EXPECT_GE(look->az_deg, 0.0);
    EXPECT_LT(look->az_deg, 360.0);
    // Elevation 20 + 10 sin(pi t / 120 min): a cubic over 10-minute rows is off by at most
    // (3/128) h^4 max|d4 el/dt4| = 0.0011 deg at an interval's middle.
    EXPECT_NEAR(look->el_deg, 20.0 + 10.0 * std::sin(std::numbers::pi * minute / 120.0), 1.2e-3)
        << minute;
    // Range rate is linear in time and range its integral: the cubic reproduces both, to the
    // 86 us rounding of the JDUT column (1.4e-8 km/s here).
    EXPECT_NEAR(look->range_rate_km_s, -1.5 + 0.01 * minute, 1e-7) << minute;
    EXPECT_NEAR(look->range_km, 2.5e6 + 60.0 * (-1.5 * minute + 0.005 * minute * minute), 0.01)
        << minute;
  }
}

TEST(HorizonsObserver, CalendarTimesAndKilometreRangesAreRead) {
  const std::string text = fixture("observer_north.txt");
  // Without the JDUT column the calendar column gives the times.
  auto calendar_only = ObserverTable::parse_horizons_observer(
      replaced(text, "Date_________JDUT", "Date_________JDTT"));
  ASSERT_TRUE(calendar_only.ok()) << calendar_only.error().message;
  auto look = calendar_only->at(test::calendar(2025, 3, 1, 0, 55, 0.0));
  ASSERT_TRUE(look.ok()) << look.error().message;
  EXPECT_NEAR(look->az_deg, 359.5, 1e-6);
  // RANGE_UNITS='KM' changes the footer's delta units; the numbers are then taken as km.
  auto km = ObserverTable::parse_horizons_observer(
      replaced(text, "Units: AU and KM/S", "Units: KM and KM/S"));
  ASSERT_TRUE(km.ok()) << km.error().message;
  auto first = km->at(test::calendar(2025, 3, 1, 0, 0, 0.0));
  ASSERT_TRUE(first.ok());
  EXPECT_NEAR(first->range_km, 2.5e6 / kAuKm, 1e-13);
}

TEST(HorizonsObserver, ErrorsNameTheProblem) {
  const std::string text = fixture("observer_north.txt");
  auto table = ObserverTable::parse_horizons_observer(text);
  ASSERT_TRUE(table.ok()) << table.error().message;
  auto late = table->at(test::calendar(2025, 3, 1, 2, 0, 1.0));
  ASSERT_FALSE(late.ok());
  EXPECT_TRUE(test::contains(late.error().message, "covers UTC JD 2460735.5 .. 2460735.58333"))
      << late.error().message;
  const std::string na = observer_error(replaced(text, "  355.000000", "        n.a."));
  EXPECT_TRUE(test::contains(na, "line 33")) << na;
  EXPECT_TRUE(test::contains(na, "topocentric")) << na;
  const std::string no_az = observer_error(replaced(text, "Azi_(a-app)", "Azi_(r-app)"));
  EXPECT_TRUE(test::contains(no_az, "QUANTITIES 4")) << no_az;
  const std::string no_delta = observer_error(replaced(text, "delta,", "r,"));
  EXPECT_TRUE(test::contains(no_delta, "QUANTITIES 20")) << no_delta;
  const std::string bad = observer_error(replaced(text, "-1.4000000", "-1.40000x0"));
  EXPECT_TRUE(test::contains(bad, "line 33 (2025-Mar-01 00:10")) << bad;
  const std::string no_site =
      observer_error(replaced(text, "Center geodetic :", "Centre geodetic:"));
  EXPECT_TRUE(test::contains(no_site, "Center geodetic")) << no_site;
  EXPECT_TRUE(test::contains(observer_error(replaced(text, "$$SOE", "")), "no $$SOE"));
}

// Truncations and single-byte damage anywhere in the files give a table or an error, never a crash
// (run under the ASan+UBSan preset to catch out-of-range reads).
TEST(Horizons, DamagedFilesNeverCrash) {
  for (const char* name :
       {"moon_vectors_csv_kms.txt", "moon_vectors_text_aud.txt", "observer_north.txt"}) {
    const std::string text = fixture(name);
    for (std::size_t cut = 0; cut < text.size(); cut += 97) {
      std::string damaged = text;
      damaged[cut] = (cut % 2 == 0) ? ',' : '\n';
      for (const std::string& t : {text.substr(0, cut), damaged}) {
        auto vectors = SpacecraftTable::parse_horizons_vectors(t);
        auto observer = ObserverTable::parse_horizons_observer(t);
        if (vectors.ok()) {
          EXPECT_TRUE(vectors->at(vectors->nodes().front().tdb).ok());
        }
        if (observer.ok()) {
          EXPECT_GE(observer->size(), 2U);
        }
      }
    }
  }
}

}  // namespace
}  // namespace azt::astro
