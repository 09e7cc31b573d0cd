// chronyc's CSV reports (docs/time.md): a synchronised GPS server, chronyd just started, the
// sources table with a refclock and servers, and every way a line can be unreadable.
#include "azt/timekeeping/chrony_report.hpp"

#include <gtest/gtest.h>

#include <string>

namespace azt::timekeeping {
namespace {

// chrony 4.3 `chronyc -c tracking` on a GPS-disciplined server (fields as chronyc(1) lists them).
constexpr const char* kSynced =
    "47505300,GPS,1,1764057600.123456789,-0.000001500,0.000002100,0.000012000,-12.345,0.001,"
    "0.050,0.000000001,0.000025000,16.0,Normal\n";
constexpr const char* kStarting =
    "00000000,,0,0.000000000,0.000000000,0.000000000,0.000000000,0.000,0.000,0.000,1.000000000,"
    "1.000000000,0.0,Not synchronised\n";

TEST(ChronyTracking, ReadsASynchronisedServer) {
  const auto t = parse_chrony_tracking(kSynced);
  ASSERT_TRUE(t) << t.error().message;
  EXPECT_EQ(t->ref_id_hex, "47505300");
  EXPECT_EQ(t->ref_name, "GPS");
  EXPECT_EQ(t->stratum, 1);
  EXPECT_DOUBLE_EQ(t->ref_time_unix_s, 1764057600.123456789);
  // chronyc's "System time" is the correction still to apply: -1.5 µs to apply is 1.5 µs fast.
  EXPECT_DOUBLE_EQ(t->system_offset_s, 0.0000015);
  EXPECT_DOUBLE_EQ(t->last_offset_s, 0.0000021);
  EXPECT_DOUBLE_EQ(t->frequency_ppm, -12.345);
  EXPECT_DOUBLE_EQ(t->root_dispersion_s, 0.000025);
  EXPECT_DOUBLE_EQ(t->update_interval_s, 16.0);
  EXPECT_EQ(t->leap, "Normal");
  EXPECT_TRUE(t->synchronised());
}

TEST(ChronyTracking, JustStartedIsNotSynchronised) {
  const auto t = parse_chrony_tracking(kStarting);
  ASSERT_TRUE(t) << t.error().message;
  EXPECT_EQ(t->stratum, 0);
  EXPECT_EQ(t->leap, "Not synchronised");
  EXPECT_FALSE(t->synchronised());
}

TEST(ChronyTracking, UnreadableReportsNameTheirFault) {
  EXPECT_FALSE(parse_chrony_tracking(""));
  const auto short_line = parse_chrony_tracking("47505300,GPS,1\n");
  ASSERT_FALSE(short_line);
  EXPECT_NE(short_line.error().message.find("3 fields, expected 14"), std::string::npos);
  std::string bad_stratum = kSynced;
  bad_stratum.replace(bad_stratum.find(",1,"), 3, ",one,");
  const auto r = parse_chrony_tracking(bad_stratum);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("stratum"), std::string::npos) << r.error().message;
  std::string nan_offset = kSynced;
  nan_offset.replace(nan_offset.find("-0.000001500"), 12, "nan");
  EXPECT_FALSE(parse_chrony_tracking(nan_offset));
  // chronyc's error text on stdout (no chronyd) is not a report.
  EXPECT_FALSE(parse_chrony_tracking("506 Cannot talk to daemon\n"));
}

TEST(ChronySources, ReadsRefclocksAndServers) {
  const auto s = parse_chrony_sources(
      "#,*,GPS,0,2,377,3,-0.000012345,-0.000012345,0.000500000\n"
      "#,?,PPS,0,4,0,4294967295,0.000000000,0.000000000,0.000000000\n"
      "^,+,192.168.1.10,2,6,17,-,0.001000000,0.001000000,0.010000000\n");
  ASSERT_TRUE(s) << s.error().message;
  ASSERT_EQ(s->size(), 3U);
  const ChronySource& gps = (*s)[0];
  EXPECT_EQ(mode_name(gps.mode), "refclock");
  EXPECT_EQ(state_name(gps.state), "selected");
  EXPECT_EQ(gps.name, "GPS");
  EXPECT_EQ(gps.poll_log2_s, 2);
  EXPECT_EQ(gps.reach, 0377);  // octal: the last eight polls all answered
  ASSERT_TRUE(gps.last_rx_s.has_value());
  EXPECT_DOUBLE_EQ(*gps.last_rx_s, 3.0);
  EXPECT_DOUBLE_EQ(gps.offset_s, -0.000012345);
  EXPECT_DOUBLE_EQ(gps.error_s, 0.0005);
  EXPECT_FALSE((*s)[1].last_rx_s.has_value()) << "2^32-1 s is never";
  EXPECT_EQ(state_name((*s)[1].state), "unusable");
  EXPECT_EQ(mode_name((*s)[2].mode), "server");
  EXPECT_EQ((*s)[2].stratum, 2);
  EXPECT_FALSE((*s)[2].last_rx_s.has_value()) << "'-' is never";
}

TEST(ChronySources, NoSourcesIsAnEmptyList) {
  const auto s = parse_chrony_sources("");
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->empty());
}

TEST(ChronySources, AnUnreadableLineIsNamed) {
  const auto wrong_count =
      parse_chrony_sources("#,*,GPS,0,2,377,3,0,0,0\n^,+,a.example,2,6,17,1,0,0\n");
  ASSERT_FALSE(wrong_count);
  EXPECT_NE(wrong_count.error().message.find("line 2"), std::string::npos);
  const auto bad_reach = parse_chrony_sources("#,*,GPS,0,2,389,3,0,0,0\n");  // 9 is not octal
  ASSERT_FALSE(bad_reach);
  EXPECT_NE(bad_reach.error().message.find("reach"), std::string::npos);
  EXPECT_FALSE(parse_chrony_sources("#,**,GPS,0,2,377,3,0,0,0\n"));
}

TEST(ChronyNames, EveryMarkHasAWord) {
  EXPECT_EQ(mode_name('='), "peer");
  EXPECT_EQ(mode_name('!'), "unknown");
  EXPECT_EQ(state_name('+'), "combined");
  EXPECT_EQ(state_name('-'), "not_combined");
  EXPECT_EQ(state_name('x'), "falseticker");
  EXPECT_EQ(state_name('~'), "too_variable");
  EXPECT_EQ(state_name('!'), "unknown");
}

}  // namespace
}  // namespace azt::timekeeping
