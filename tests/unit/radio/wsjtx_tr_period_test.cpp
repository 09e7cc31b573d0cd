// The T/R period of a WSJT-X Status (azt/radio/wsjtx_tr_period.hpp): the Status's own when it
// gives one, else the period WSJT-X fixes for the mode (FT8 15 s, FT4 7.5 s, …), else unknown.
#include "azt/radio/wsjtx_tr_period.hpp"

#include <gtest/gtest.h>

#include <string>

namespace azt::radio {
namespace {

/// A Status as WSJT-X 2.2 and later send it in `mode`, with the T/R period field as given.
WsjtxStatus status(const std::string& mode, std::uint32_t tr_period_s = kWsjtxNotApplicable) {
  WsjtxStatus s;
  s.mode = mode;
  s.sub_mode = WsjtxStatus::SubMode{};
  s.periods = WsjtxStatus::Periods{};
  s.periods->tr_period_s = tr_period_s;
  return s;
}

TEST(WsjtxTrPeriod, TheModesWsjtxFixesTheirPeriodFor) {
  // WSJT-X sends "not applicable" in these (widgets/mainwindow.cpp, statusUpdate).
  EXPECT_EQ(tr_period_s(status("FT8")), 15.0);
  EXPECT_EQ(tr_period_s(status("FT4")), 7.5);
  EXPECT_EQ(tr_period_s(status("JT4")), 60.0);
  EXPECT_EQ(tr_period_s(status("JT9")), 60.0);
  EXPECT_EQ(tr_period_s(status("JT65")), 60.0);
  EXPECT_EQ(tr_period_s(status("WSPR")), 120.0);
}

TEST(WsjtxTrPeriod, AnOlderWsjtxThatSendsNoPeriodFieldAtAll) {
  WsjtxStatus s;  // a Status that ends before the Periods group (WSJT-X before 2.2)
  s.mode = "FT8";
  EXPECT_EQ(tr_period_s(s), 15.0);
  s.mode = "JT65";
  EXPECT_EQ(tr_period_s(s), 60.0);
}

TEST(WsjtxTrPeriod, ThePeriodTheStatusGivesWins) {
  EXPECT_EQ(tr_period_s(status("Q65", 30)), 30.0);
  EXPECT_EQ(tr_period_s(status("FST4", 1800)), 1800.0);
  EXPECT_EQ(tr_period_s(status("MSK144", 15)), 15.0);
  EXPECT_EQ(tr_period_s(status("FT8", 30)), 30.0);  // whatever a newer WSJT-X may say
}

TEST(WsjtxTrPeriod, UnknownWhereTheOperatorChoosesItAndTheStatusSaysNothing) {
  for (const char* mode :
       {"Q65", "FST4", "FST4W", "MSK144", "FreqCal", "Echo", "", "ft8", "FT8 "}) {
    EXPECT_EQ(tr_period_s(status(mode)), std::nullopt) << mode;
    EXPECT_EQ(tr_period_s(status(mode, 0)), std::nullopt) << mode;
  }
  WsjtxStatus fast = status("JT9");
  fast.sub_mode->fast_mode = true;  // JT9's fast sub-modes show the period box: 5 to 30 s
  EXPECT_EQ(tr_period_s(fast), std::nullopt);
  fast.periods->tr_period_s = 10;
  EXPECT_EQ(tr_period_s(fast), 10.0);
  EXPECT_EQ(mode_tr_period_s("FT8", true), 15.0);  // fast mode is JT9's alone
}

TEST(WsjtxTrPeriod, ADecodedFt8StatusFromWsjtx26) {
  // WSJT-X 2.6's FT8 Status as decoded: T/R period 0xffffffff, its period still 15 s.
  std::string d;
  const auto u32 = [&d](std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) d += static_cast<char>((v >> shift) & 0xffU);
  };
  const auto utf8 = [&](const std::string& t) {
    u32(static_cast<std::uint32_t>(t.size()));
    d += t;
  };
  u32(kWsjtxMagic);
  u32(2);
  u32(1);
  utf8("WSJT-X");
  u32(0);
  u32(14074000);
  utf8("FT8");
  utf8("K1ABC");
  utf8("-10");
  utf8("FT8");
  d += std::string("\1\0\0", 3);  // Tx enabled, transmitting, decoding
  u32(1500);
  u32(1500);
  utf8("W1AW");
  utf8("FN31");
  utf8("FN42");
  d += std::string("\0", 1);  // Tx watchdog
  utf8("");
  d += std::string("\0\0", 2);  // fast mode, special operation mode
  u32(kWsjtxNotApplicable);     // frequency tolerance
  u32(kWsjtxNotApplicable);     // T/R period
  utf8("Default");
  const auto decoded = decode_wsjtx_datagram(d);
  ASSERT_TRUE(decoded.ok()) << decoded.error().message;
  EXPECT_EQ(tr_period_s(std::get<WsjtxStatus>(decoded.value())), 15.0);
}

}  // namespace
}  // namespace azt::radio
