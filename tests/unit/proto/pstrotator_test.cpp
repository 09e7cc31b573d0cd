// PstRotator UDP codec and handler. Datagrams are the ones in
// reference/rotator-controllers-and-protocols.md §8.6 and what Hamlib rigs/dummy/rot_pstrotator.c
// sends (targets formatted "%f.2", so "123.000000.2"); replies follow the "AZ:%g" / "EL:%g" reader.
#include "azt/proto/pstrotator.hpp"

#include <gtest/gtest.h>

#include <array>
#include <charconv>
#include <cmath>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "fake_rotator_service.hpp"

namespace azt::proto {
namespace {

using Calls = std::vector<std::string>;

PstCommand parse_ok(std::string_view datagram, const TargetLimits& limits = {}) {
  auto parsed = parse_pstrotator(datagram, limits);
  if (!parsed) {
    ADD_FAILURE() << "'" << datagram << "': " << parsed.error().message;
    return {};
  }
  return *parsed;
}

/// What Hamlib's "%f.2" produces: six decimals, then a literal ".2".
std::string hamlib_number(double value) {
  std::array<char, 64> buffer{};
  const auto [ptr, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                       std::chars_format::fixed, 6);
  EXPECT_EQ(ec, std::errc{});
  return std::string(buffer.data(), ptr) + ".2";
}

TEST(PstRotator, ParsesReferenceDatagrams) {
  EXPECT_EQ(*parse_ok("<PST><AZIMUTH>123.4</AZIMUTH></PST>").az_deg, 123.4);
  const auto both = parse_ok("<PST><AZIMUTH>85</AZIMUTH><ELEVATION>25</ELEVATION></PST>");
  EXPECT_EQ(both.az_deg, 85.0);
  EXPECT_EQ(both.el_deg, 25.0);
  EXPECT_TRUE(parse_ok("<PST><STOP>1</STOP></PST>").stop);
  EXPECT_TRUE(parse_ok("<PST><PARK>1</PARK></PST>").park);
  EXPECT_TRUE(parse_ok("<PST>AZ?</PST>").query_az);
  EXPECT_TRUE(parse_ok("<PST>EL?</PST>").query_el);
  EXPECT_EQ(parse_ok("<PST><STOP>0</STOP></PST>"), PstCommand{});
}

TEST(PstRotator, ToleratesHamlibNumbersCaseAndWhitespace) {
  EXPECT_EQ(*parse_ok("<PST><AZIMUTH>123.000000.2</AZIMUTH></PST>").az_deg, 123.0);
  EXPECT_EQ(*parse_ok("<PST><ELEVATION>-0.000000.2</ELEVATION></PST>").el_deg, 0.0);
  const auto relaxed = parse_ok(" <pst> <Azimuth> +12.5 </Azimuth>\tel? </PST>\r\n");
  EXPECT_EQ(relaxed.az_deg, 12.5);
  EXPECT_TRUE(relaxed.query_el);
  EXPECT_FALSE(relaxed.query_az);
}

TEST(PstRotator, IgnoresUiTags) {
  EXPECT_EQ(parse_ok("<PST><TRACK>1</TRACK><QRA>JO31jg</QRA><ON>0</ON></PST>"), PstCommand{});
}

TEST(PstRotator, Rejects) {
  const std::vector<std::string_view> bad = {
      "",
      "<PST>",
      "AZ?",
      "<PST>AZ?",
      "<PST>XY?</PST>",
      "<PST>AZ</PST>",
      "<PST><AZIMUTH>nan</AZIMUTH></PST>",
      "<PST><AZIMUTH>inf</AZIMUTH></PST>",
      "<PST><AZIMUTH>1e2</AZIMUTH></PST>",
      "<PST><AZIMUTH>12x</AZIMUTH></PST>",
      "<PST><AZIMUTH>123.4.x</AZIMUTH></PST>",
      "<PST><AZIMUTH>.5</AZIMUTH></PST>",
      "<PST><AZIMUTH>-</AZIMUTH></PST>",
      "<PST><AZIMUTH></AZIMUTH></PST>",
      "<PST><AZIMUTH>500</AZIMUTH></PST>",
      "<PST><ELEVATION>-1</ELEVATION></PST>",
      "<PST><AZIMUTH>1</ELEVATION></PST>",
      "<PST><AZIMUTH>1</PST>",
      "<PST><AZIMUTH>1</AZIMUTH",
      "<PST><ANT>1</ANT></PST>",
      "<PST><STOP>2</STOP></PST>",
      "<PST><QRA>JO31 jg</QRA></PST>",
      "<PST><A1>1</A1></PST>",
      "<PST></PST></PST>",
  };
  for (const auto datagram : bad) {
    EXPECT_FALSE(parse_pstrotator(datagram).ok()) << "'" << datagram << "'";
  }
  const TargetLimits narrow{0.0, 360.0, 0.0, 90.0};
  EXPECT_FALSE(parse_pstrotator("<PST><AZIMUTH>-10</AZIMUTH></PST>", narrow).ok());
  EXPECT_TRUE(parse_pstrotator("<PST><AZIMUTH>-10</AZIMUTH></PST>").ok());  // −180..450 default
}

TEST(PstRotator, DatagramsAreBounded) {
  const std::string_view head = "<PST>";
  const std::string_view tail = "AZ?</PST>";
  std::string at_limit(head);
  at_limit += std::string(kPstMaxDatagramBytes - head.size() - tail.size(), ' ');
  at_limit += tail;
  ASSERT_EQ(at_limit.size(), kPstMaxDatagramBytes);
  EXPECT_TRUE(parse_pstrotator(at_limit).ok());
  EXPECT_FALSE(parse_pstrotator(at_limit + " ").ok());
}

TEST(PstRotator, FormatsReplies) {
  EXPECT_EQ(format_pstrotator_angle("AZ", 123.44), "AZ:123.4\r");
  EXPECT_EQ(format_pstrotator_angle("EL", 45.56), "EL:45.6\r");
  EXPECT_EQ(format_pstrotator_angle("EL", -0.04), "EL:0.0\r");
  EXPECT_EQ(format_pstrotator_angle("EL", -2.0), "EL:-2.0\r");
  EXPECT_EQ(format_pstrotator_angle("AZ", std::nan("")), "");
}

TEST(PstRotator, HandlerAppliesRequestsAndAnswersQueries) {
  test::FakeRotatorService service;
  const TargetLimits limits;
  EXPECT_EQ(handle_pstrotator_datagram("<PST>AZ?</PST>", service, "u", limits), "AZ:123.4\r");
  EXPECT_EQ(handle_pstrotator_datagram("<PST>EL?</PST>", service, "u", limits), "EL:45.6\r");
  EXPECT_EQ(handle_pstrotator_datagram("<PST>AZ? EL?</PST>", service, "u", limits),
            "AZ:123.4\rEL:45.6\r");
  service.record_activity = false;  // from here on, only the requests
  const std::string set =
      "<PST><AZIMUTH>" + hamlib_number(200.0) + "</AZIMUTH><ELEVATION>30</ELEVATION></PST>";
  EXPECT_EQ(handle_pstrotator_datagram(set, service, "u", limits), "");
  EXPECT_EQ(handle_pstrotator_datagram("<PST><AZIMUTH>10</AZIMUTH></PST>", service, "u", limits),
            "");
  EXPECT_EQ(handle_pstrotator_datagram("<PST><ELEVATION>5</ELEVATION></PST>", service, "u", limits),
            "");
  EXPECT_EQ(handle_pstrotator_datagram("<PST><STOP>1</STOP></PST>", service, "u", limits), "");
  EXPECT_EQ(handle_pstrotator_datagram("<PST><PARK>1</PARK></PST>", service, "u", limits), "");
  EXPECT_EQ(service.calls,
            (Calls{"activity u", "activity u", "activity u", "goto_position u 200 30",
                   "goto_axis u az 10", "goto_axis u el 5", "stop u all", "park u"}));
}

TEST(PstRotator, HandlerRejectsBadDatagramsAndStalePositions) {
  test::FakeRotatorService service;
  const TargetLimits limits;
  EXPECT_EQ(
      handle_pstrotator_datagram("<PST><AZIMUTH>nan</AZIMUTH>AZ?</PST>", service, "u", limits), "");
  EXPECT_EQ(service.calls, (Calls{"activity u"}));  // nothing of a bad datagram is applied
  EXPECT_EQ(service.position_queries, 0);
  service.report = std::nullopt;
  EXPECT_EQ(handle_pstrotator_datagram("<PST>AZ?</PST>", service, "u", limits), "");
  EXPECT_EQ(service.position_queries, 1);
}

TEST(PstRotator, SeededHamlibTargetsRoundTrip) {
  std::mt19937_64 rng(0x7057'0001);
  std::uniform_real_distribution<double> az_dist(-180.0, 450.0);
  std::uniform_real_distribution<double> el_dist(0.0, 90.0);
  for (int i = 0; i < 2000; ++i) {
    const double az = az_dist(rng);
    const double el = el_dist(rng);
    const std::string datagram = "<PST><AZIMUTH>" + hamlib_number(az) + "</AZIMUTH><ELEVATION>" +
                                 hamlib_number(el) + "</ELEVATION></PST>";
    const auto parsed = parse_pstrotator(datagram);
    ASSERT_TRUE(parsed.ok()) << datagram;
    EXPECT_NEAR(*parsed->az_deg, az, 5e-7) << datagram;
    EXPECT_NEAR(*parsed->el_deg, el, 5e-7) << datagram;
  }
}

TEST(PstRotator, SeededRandomDatagramsNeverCrash) {
  std::mt19937_64 rng(0x7057'0BAD);
  const std::string_view alphabet = "<>/PSTAZIMUTHELVONRKQ?0123456789.-+ naif\r\x01";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  std::uniform_int_distribution<std::size_t> len(0, 80);
  const TargetLimits limits;
  for (int i = 0; i < 5000; ++i) {
    std::string datagram = "<PST>";
    datagram.append(len(rng), ' ');
    for (std::size_t j = 5; j < datagram.size(); ++j) datagram[j] = alphabet[pick(rng)];
    datagram += "</PST>";
    const auto parsed = parse_pstrotator(datagram, limits);
    if (!parsed) continue;
    EXPECT_TRUE(!parsed->az_deg || limits.accepts_az(*parsed->az_deg)) << datagram;
    EXPECT_TRUE(!parsed->el_deg || limits.accepts_el(*parsed->el_deg)) << datagram;
  }
}

}  // namespace
}  // namespace azt::proto
