// Element-set files (docs/satellites.md): CCSDS OMM in XML, JSON, KVN and CSV against the TLE
// parser.
//
// Fixtures: tests/data/omm/catalogue.{tle,xml,json,kvn,csv}, four objects (LEO, polar, Molniya,
// a decaying object with n̈ and a negative B*), written by tests/data/omm/make_fixtures.py with
// Debian's python3-sgp4 2.15 (run /usr/bin/python3 tests/data/omm/make_fixtures.py): the OMM
// numbers are the TLE's fields as printed, the OMM epoch is python-sgp4's conversion of the TLE
// epoch to whole microseconds (sat_epoch_datetime), and the script checks that sgp4.omm reads
// each file back into a satellite that propagates like the TLE. So the TLE parser is the
// reference here: an OMM must give the same Elements, the epoch within 1e-9 day (python keeps
// whole microseconds, 1.2e-11 day).

#include "satellites/element_sets.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "azt/orbit/omm_record.hpp"
#include "azt/orbit/tle.hpp"

namespace azt::app {
namespace {

std::string fixture(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(AZT_TEST_DATA_DIR) / "omm" / name;
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << path;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Replaces the first `from` after position `after` (which must be there) by `to`.
std::string replaced(std::string text, std::string_view from, std::string_view to,
                     std::size_t after = 0) {
  const std::size_t at = text.find(from, after);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string joined(const std::vector<std::string>& errors) {
  std::string all;
  for (const std::string& e : errors) all += e + "\n";
  return all;
}

void expect_same(const orbit::Elements& omm, const orbit::Elements& tle) {
  SCOPED_TRACE(tle.name);
  EXPECT_EQ(omm.name, tle.name);
  EXPECT_EQ(omm.catalog, tle.catalog);
  EXPECT_EQ(omm.intl_designator, tle.intl_designator);
  EXPECT_EQ(omm.classification, tle.classification);
  EXPECT_EQ(omm.epoch_jd, tle.epoch_jd);
  EXPECT_NEAR(omm.epoch_jd_frac, tle.epoch_jd_frac, 1e-9);
  EXPECT_EQ(omm.mean_motion_dot, tle.mean_motion_dot);
  // The TLE parser reads the implied-exponent fields as Vallado's twoline2rv does (mantissa
  // times pow(10, exponent)), which may differ from the decimal's nearest double by an ulp.
  EXPECT_DOUBLE_EQ(omm.mean_motion_ddot, tle.mean_motion_ddot);
  EXPECT_DOUBLE_EQ(omm.bstar, tle.bstar);
  EXPECT_EQ(omm.inclination_deg, tle.inclination_deg);
  EXPECT_EQ(omm.raan_deg, tle.raan_deg);
  EXPECT_EQ(omm.eccentricity, tle.eccentricity);
  EXPECT_EQ(omm.arg_perigee_deg, tle.arg_perigee_deg);
  EXPECT_EQ(omm.mean_anomaly_deg, tle.mean_anomaly_deg);
  EXPECT_EQ(omm.mean_motion_rev_day, tle.mean_motion_rev_day);
  EXPECT_EQ(omm.element_set_no, tle.element_set_no);
  EXPECT_EQ(omm.rev_at_epoch, tle.rev_at_epoch);
}

class OmmFixture : public ::testing::TestWithParam<const char*> {};

TEST_P(OmmFixture, GivesTheTleParsersElements) {
  const std::string format = GetParam();
  const orbit::TleParse tles = orbit::parse_tle_catalogue(fixture("catalogue.tle"));
  ASSERT_TRUE(tles.errors.empty()) << joined(tles.errors);
  ASSERT_EQ(tles.sets.size(), 4U);
  const ElementSetFile file = parse_element_sets(fixture("catalogue." + format), "f");
  EXPECT_EQ(file.format, format);
  EXPECT_TRUE(file.errors.empty()) << joined(file.errors);
  ASSERT_EQ(file.sets.size(), tles.sets.size());
  for (std::size_t i = 0; i < tles.sets.size(); ++i) expect_same(file.sets[i], tles.sets[i]);
}

INSTANTIATE_TEST_SUITE_P(ElementSets, OmmFixture, ::testing::Values("xml", "json", "kvn", "csv"));

TEST(ElementSets, TleFilesGoThroughTheCoreParser) {
  const ElementSetFile file = parse_element_sets(fixture("catalogue.tle"), "cat.txt");
  EXPECT_EQ(file.format, "tle");
  EXPECT_EQ(file.sets.size(), 4U);
  const ElementSetFile bad = parse_element_sets("ISS\n1 25544U\n", "cat.txt");
  ASSERT_FALSE(bad.errors.empty());
  EXPECT_EQ(bad.errors[0].rfind("cat.txt: ", 0), 0U) << bad.errors[0];
}

TEST(ElementSets, DetectsTheFormatFromTheContent) {
  const auto format_of = [](std::string_view text) { return parse_element_sets(text, "x").format; };
  EXPECT_EQ(format_of("  \n<?xml version=\"1.0\"?><ndm/>"), "xml");
  EXPECT_EQ(format_of("\xEF\xBB\xBF[]"), "json");
  EXPECT_EQ(format_of("\r\n{\"OBJECT_NAME\": \"X\"}"), "json");
  EXPECT_EQ(format_of("COMMENT from a file\nCCSDS_OMM_VERS = 2.0\n"), "kvn");
  EXPECT_EQ(format_of("OBJECT_NAME,EPOCH,MEAN_MOTION\n"), "csv");
  EXPECT_EQ(format_of("\"OBJECT_NAME\",\"MEAN_MOTION\"\r\n"), "csv");
  EXPECT_EQ(format_of("NOT A TLE\n"), "tle");
  EXPECT_EQ(format_of(""), "empty");
  EXPECT_EQ(format_of(" \r\n\t\n"), "empty");
}

TEST(ElementSets, AnEmptyOrHollowFileIsAnError) {
  for (const char* text : {"", "\n\n", "[]", "<ndm></ndm>", "OBJECT_NAME,MEAN_MOTION\n"}) {
    const ElementSetFile file = parse_element_sets(text, "sats.txt");
    EXPECT_TRUE(file.sets.empty()) << text;
    ASSERT_EQ(file.errors.size(), 1U) << text;
    EXPECT_NE(file.errors[0].find("sats.txt: "), std::string::npos);
    EXPECT_NE(file.errors[0].find("no element sets"), std::string::npos) << file.errors[0];
  }
}

/// Breaks NOAA 19's MEAN_MOTION in a fixture (the second object) and checks the message.
void expect_only_noaa_lost(const std::string& format, std::string_view from, std::string_view to,
                           const std::string& message) {
  SCOPED_TRACE(format);
  const std::string text = fixture("catalogue." + format);
  const std::string broken = replaced(text, from, to, text.find("NOAA 19"));
  const ElementSetFile file = parse_element_sets(broken, "sats." + format);
  ASSERT_EQ(file.sets.size(), 3U) << joined(file.errors);
  EXPECT_EQ(file.sets[0].name, "ISS (ZARYA)");
  EXPECT_EQ(file.sets[1].name, "MOLNIYA 2-9");
  EXPECT_EQ(file.sets[2].name, "DEBRIS 2024");
  ASSERT_EQ(file.errors.size(), 1U) << joined(file.errors);
  EXPECT_EQ(file.errors[0], message);
}

TEST(ElementSets, OneBadObjectDoesNotHideTheOthers) {
  expect_only_noaa_lost("json", "14.12720431", "\"abc\"",
                        "sats.json: object 2 (NOAA 19): MEAN_MOTION: 'abc' is not a number");
  expect_only_noaa_lost(
      "xml", "14.12720431", "abc",
      "sats.xml: object 2 (NOAA 19): line 41: MEAN_MOTION: 'abc' is not a number");
  expect_only_noaa_lost(
      "kvn", "14.12720431", "abc",
      "sats.kvn: object 2 (NOAA 19): line 40: MEAN_MOTION: 'abc' is not a number");
  expect_only_noaa_lost("csv", "14.12720431", "abc",
                        "sats.csv: object 2 (NOAA 19): line 3: MEAN_MOTION: 'abc' is not a number");
}

/// The first object of the KVN fixture (ISS) alone, to break one keyword at a time.
std::string iss_kvn() {
  const std::string text = fixture("catalogue.kvn");
  return text.substr(0, text.find("CCSDS_OMM_VERS", 1));
}

std::string error_of(const std::string& text, std::string_view source = "iss.kvn") {
  const ElementSetFile file = parse_element_sets(text, std::string(source));
  EXPECT_TRUE(file.sets.empty()) << text;
  return file.errors.size() == 1 ? file.errors[0] : "errors: " + joined(file.errors);
}

TEST(ElementSets, TheKvnBaseIsGood) {
  const ElementSetFile file = parse_element_sets(iss_kvn(), "iss.kvn");
  ASSERT_EQ(file.sets.size(), 1U) << joined(file.errors);
  EXPECT_EQ(file.sets[0].catalog, "25544");
  EXPECT_EQ(file.sets[0].intl_designator, "98067A");
}

TEST(ElementSets, NamesEveryErrorClass) {
  const std::string iss = iss_kvn();
  const std::string prefix = "iss.kvn: object 1 (ISS (ZARYA)): ";
  const auto broken = [&](std::string_view from, std::string_view to) {
    return error_of(replaced(iss, from, to));
  };
  EXPECT_EQ(broken("BSTAR = 0.00030015\n", ""),
            prefix + "BSTAR: missing from the object starting at line 1");
  EXPECT_EQ(broken("MEAN_ELEMENT_THEORY = SGP4\n", ""),
            prefix + "MEAN_ELEMENT_THEORY: missing from the object starting at line 1");
  EXPECT_EQ(broken("MEAN_ELEMENT_THEORY = SGP4", "MEAN_ELEMENT_THEORY = SGP4-XP"),
            prefix +
                "line 10: MEAN_ELEMENT_THEORY: 'SGP4-XP': only SGP4 mean elements can be "
                "propagated");
  EXPECT_EQ(broken("EPHEMERIS_TYPE = 0", "EPHEMERIS_TYPE = 4"),
            prefix +
                "line 19: EPHEMERIS_TYPE: 4 (SGP4-XP) is not 0 (SGP4): only SGP4 elements "
                "can be propagated");
  EXPECT_EQ(broken("REF_FRAME = TEME", "REF_FRAME = GCRF"),
            prefix + "line 8: REF_FRAME: 'GCRF': SGP4 elements need TEME");
  EXPECT_EQ(broken("INCLINATION = 51.6416", "INCLINATION = 180.5"),
            prefix + "line 15: INCLINATION: '180.5' out of range 0–180");
  EXPECT_EQ(broken("RA_OF_ASC_NODE = 247.4627", "RA_OF_ASC_NODE = -0.1"),
            prefix + "line 16: RA_OF_ASC_NODE: '-0.1' out of range 0–360");
  EXPECT_EQ(broken("ECCENTRICITY = 0.0006703", "ECCENTRICITY = 1.0"),
            prefix + "line 14: ECCENTRICITY: '1.0' out of range 0 ≤ e < 1");
  EXPECT_EQ(broken("MEAN_MOTION = 15.49815361", "MEAN_MOTION = 0"),
            prefix + "line 13: MEAN_MOTION: '0' must be above 0 rev/day");
  EXPECT_EQ(broken("BSTAR = 0.00030015", "BSTAR = nan"),
            prefix + "line 24: BSTAR: 'nan' is not a number");
  EXPECT_EQ(broken("NORAD_CAT_ID = 25544", "NORAD_CAT_ID = 25544.5"),
            prefix + "line 21: NORAD_CAT_ID: '25544.5' is not a whole number");
  EXPECT_EQ(broken("CLASSIFICATION_TYPE = U", "CLASSIFICATION_TYPE = X"),
            prefix + "line 20: CLASSIFICATION_TYPE: 'X': U, C or S expected");
  EXPECT_EQ(broken("EPOCH = 2024-03-01", "EPOCH = 2024-02-30"),
            prefix + "line 12: EPOCH: day 30 out of range 1–29");
  EXPECT_EQ(broken("ORIGINATOR = CELESTRAK", "ORIGINATOR CELESTRAK"),
            prefix + "line 3: 'ORIGINATOR CELESTRAK' is not KEYWORD = value");
  EXPECT_EQ(broken("OBJECT_ID = 1998-067A", "OBJECT_ID = 1998-067A\nINCLINATION = 1"),
            prefix + "line 16: INCLINATION: given twice in one object");
}

TEST(ElementSets, TheoryIsOptionalOnlyInCelesTraksFlatFormats) {
  // CelesTrak's JSON and CSV carry no metadata; SGP4 is what GP data are.
  const std::string json = fixture("catalogue.json");
  EXPECT_EQ(parse_element_sets(json, "j").sets.size(), 4U);
  const std::string xp = replaced(json, "\"EPHEMERIS_TYPE\": 0", "\"EPHEMERIS_TYPE\": 4");
  const ElementSetFile file = parse_element_sets(xp, "j");
  EXPECT_EQ(file.sets.size(), 3U);
  ASSERT_EQ(file.errors.size(), 1U);
  EXPECT_NE(file.errors[0].find("object 1 (ISS (ZARYA)): EPHEMERIS_TYPE: 4 (SGP4-XP)"),
            std::string::npos)
      << file.errors[0];
  const std::string xml = fixture("catalogue.xml");
  const std::string no_theory =
      replaced(xml, "<MEAN_ELEMENT_THEORY>SGP4</MEAN_ELEMENT_THEORY>", "");
  const ElementSetFile xml_file = parse_element_sets(no_theory, "x.xml");
  EXPECT_EQ(xml_file.sets.size(), 3U);
  ASSERT_EQ(xml_file.errors.size(), 1U);
  EXPECT_EQ(xml_file.errors[0],
            "x.xml: object 1 (ISS (ZARYA)): MEAN_ELEMENT_THEORY: missing from the object "
            "starting at line 3");
}

TEST(ElementSets, SyntaxErrorsOfEachFormat) {
  EXPECT_EQ(error_of("<ndm><omm>\n<body>\n</omm></ndm>", "a.xml"),
            "a.xml: line 3: not well-formed XML: Start-end tags mismatch");
  EXPECT_EQ(error_of("<opm/>", "a.xml"), "a.xml: line 1: <opm> is neither <ndm> nor <omm>");
  EXPECT_EQ(error_of("<ndm>\n<omm><header/></omm></ndm>", "a.xml"),
            "a.xml: object 1: line 2: no <body><segment> in this <omm>");
  EXPECT_EQ(error_of("[{\"OBJECT_NAME\": \"X\",}]", "a.json"),
            "a.json: not valid JSON: parse error at line 1, column 22: syntax error while parsing "
            "object key - unexpected '}'; expected string literal");
  EXPECT_EQ(error_of("[{\"OBJECT_NAME\": \"X\", \"BSTAR\": [1]}]", "a.json"),
            "a.json: object 1 (X): BSTAR: a JSON array where a value is expected");
  EXPECT_EQ(error_of("[42]", "a.json"),
            "a.json: object 1: a JSON number where an object is expected");
  const std::string csv = fixture("catalogue.csv");
  const std::size_t row2 = csv.find("NOAA 19");
  EXPECT_EQ(parse_element_sets(replaced(csv, ",0,U,", ",0,U,,", row2), "a.csv").errors.at(0),
            "a.csv: object 2: line 3: 18 fields where the header has 17");
  EXPECT_EQ(parse_element_sets(replaced(csv, "NOAA 19", "\"NOAA 19", row2), "a.csv").errors.at(0),
            "a.csv: object 2: line 3: a quoted field without its closing quote");
  EXPECT_EQ(parse_element_sets("ORIGINATOR = X\nCCSDS_OMM_VERS = 2.0\n", "a.kvn").errors.at(0),
            "a.kvn: line 1: ORIGINATOR before the first CCSDS_OMM_VERS");
}

TEST(ElementSets, CsvQuotedNamesAndKvnUnits) {
  const std::string csv = fixture("catalogue.csv");
  const ElementSetFile quoted =
      parse_element_sets(replaced(csv, "NOAA 19,", "\"NOAA 19, \"\"N\"\"\","), "q.csv");
  ASSERT_EQ(quoted.sets.size(), 4U) << joined(quoted.errors);
  EXPECT_EQ(quoted.sets[1].name, "NOAA 19, \"N\"");
  const std::string kvn =
      replaced(iss_kvn(), "MEAN_MOTION = 15.49815361", "MEAN_MOTION = 15.49815361 [rev/day]");
  const ElementSetFile units = parse_element_sets(kvn, "u.kvn");
  ASSERT_EQ(units.sets.size(), 1U) << joined(units.errors);
  EXPECT_EQ(units.sets[0].mean_motion_rev_day, 15.49815361);
}

TEST(ElementSets, SpaceTrackStyleStringsAndALoneObject) {
  // Space-Track's JSON quotes every number; a lone object is a one-element file.
  const std::string text =
      R"({"OBJECT_NAME":"VANGUARD 1","OBJECT_ID":"1958-002B","EPOCH":"2020-10-13T04:52:48.472320",)"
      R"("MEAN_MOTION":"10.84869164","ECCENTRICITY":".1845686","INCLINATION":"34.2443",)"
      R"("RA_OF_ASC_NODE":"225.5254","ARG_OF_PERICENTER":"162.2516","MEAN_ANOMALY":"205.2356",)"
      R"("EPHEMERIS_TYPE":"0","CLASSIFICATION_TYPE":"U","NORAD_CAT_ID":"5","ELEMENT_SET_NO":"999",)"
      R"("REV_AT_EPOCH":"21814","BSTAR":"-.22483E-4","MEAN_MOTION_DOT":"-1.6E-7",)"
      R"("MEAN_MOTION_DDOT":"0","DECAY_DATE":null})";
  const ElementSetFile file = parse_element_sets(text, "st.json");
  ASSERT_EQ(file.sets.size(), 1U) << joined(file.errors);
  const orbit::Elements& e = file.sets[0];
  EXPECT_EQ(e.catalog, "00005");
  EXPECT_EQ(e.intl_designator, "58002B");
  EXPECT_EQ(e.eccentricity, 0.1845686);
  EXPECT_EQ(e.bstar, -0.22483e-4);
  EXPECT_EQ(e.rev_at_epoch, 21814);
}

/// One random edit of the kinds that break parsers: a byte changed (often to a delimiter), a
/// byte inserted, a span deleted or duplicated, the tail cut off.
void mutate(std::string& text, std::mt19937& rng) {
  constexpr std::string_view kSpecial = "<>/\"',=[]{}\n\r-.:eE0159T \\&;";
  const auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n == 0 ? 0 : n - 1)(rng);
  };
  const auto random_char = [&] {
    return pick(2) == 0 ? kSpecial[pick(kSpecial.size())]
                        : static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
  };
  const std::size_t at = pick(text.size() + 1);
  switch (pick(5)) {
    case 0:
      if (at < text.size()) text[at] = random_char();
      break;
    case 1:
      text.insert(at, 1, random_char());
      break;
    case 2:
      text.erase(at, pick(64));
      break;
    case 3:
      text.insert(at, text.substr(pick(text.size() + 1), pick(256)));
      break;
    default:
      text.resize(at);
      break;
  }
}

TEST(ElementSets, SurvivesRandomMutations) {
  // Seeded, so a failure reproduces; 2000 mutated files per format, 1–4 edits each.
  const auto started = std::chrono::steady_clock::now();
  for (const char* format : {"xml", "json", "kvn", "csv", "tle"}) {
    const std::string original = fixture(std::string("catalogue.") + format);
    std::mt19937 rng(20240301U);
    for (int round = 0; round < 2000; ++round) {
      std::string text = original;
      const int edits = std::uniform_int_distribution<int>(1, 4)(rng);
      for (int i = 0; i < edits; ++i) mutate(text, rng);
      const ElementSetFile file = parse_element_sets(text, "m");
      ASSERT_FALSE(file.sets.empty() && file.errors.empty()) << format << " round " << round;
      ASSERT_LE(file.sets.size() + file.errors.size(), text.size() + 1) << format;
      for (const std::string& error : file.errors) ASSERT_EQ(error.rfind("m: ", 0), 0U) << error;
    }
  }
  // Not a benchmark: a bound far above the ~0.2 s it takes, to catch a parser that loops.
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(20));
}

}  // namespace
}  // namespace azt::app

namespace azt::app {
namespace {

TEST(ElementSets, SatnogsDbJsonIsReadAsTheTlesItHolds) {
  // SatNOGS DB's /api/tle/?format=json: each object carries a three-line set's lines.
  const std::string text =
      R"j([{"tle0":"0 ISS (ZARYA)","tle1":"1 25544U 98067A   24061.52083333  .00016717  )j"
      R"j(00000-0  30119-3 0  9999","tle2":"2 25544  51.6416 247.4627 0006703 130.5360 )j"
      R"j(325.0288 15.49815488441113","tle_source":"Celestrak","norad_cat_id":25544},)j"
      R"j({"tle0":"BROKEN","tle1":"1 25544U","tle2":null}])j";
  const ElementSetFile file = parse_element_sets(text, "satnogs.json");
  EXPECT_EQ(file.format, "satnogs-json");
  ASSERT_EQ(file.sets.size(), 1U);
  EXPECT_EQ(file.sets[0].catalog, "25544");
  EXPECT_EQ(file.sets[0].name, "ISS (ZARYA)");
  ASSERT_FALSE(file.errors.empty());  // the broken entry, named
  for (const auto& e : file.errors) EXPECT_EQ(e.rfind("satnogs.json: ", 0), 0U) << e;
  // Any other JSON is OMM, as before.
  EXPECT_EQ(parse_element_sets(R"([{"OBJECT_NAME":"X"}])", "x.json").format, "json");
}

}  // namespace
}  // namespace azt::app
