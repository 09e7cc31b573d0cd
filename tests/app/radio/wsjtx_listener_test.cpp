// WSJT-X's messages as the station keeps them (radio/wsjtx_listener.hpp): the DX grid followed,
// the transmit hold and its end by a Status, a Close or silence, malformed datagrams counted.
#include "radio/wsjtx_listener.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace azt::app {
namespace {

void u32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<char>((v >> shift) & 0xff));
}

void utf8(std::string& out, const std::string& s) {
  u32(out, static_cast<std::uint32_t>(s.size()));
  out += s;
}

std::string header(std::uint32_t type) {
  std::string out;
  u32(out, 0xadbccbda);
  u32(out, 2);
  u32(out, type);
  utf8(out, "WSJT-X");
  return out;
}

/// A Status ending after its DX grid (NetworkMessage.hpp's field order).
std::string status(const std::string& dx_grid, bool transmitting, const std::string& mode = "Q65") {
  std::string out = header(1);
  u32(out, 0);
  u32(out, 1296100000);  // quint64 dial
  utf8(out, mode);
  utf8(out, "OZ1ABC");
  utf8(out, "-20");
  utf8(out, mode);
  out.push_back(1);  // tx enabled
  out.push_back(transmitting ? 1 : 0);
  out.push_back(0);  // decoding
  u32(out, 1500);
  u32(out, 1500);
  utf8(out, "W1AW");
  utf8(out, "FN31");
  utf8(out, dx_grid);
  return out;
}

struct Rig {
  double now_s = 100.0;  ///< UTC 1.7e9 + 100 s: the start of a 15 s (and a 7.5 s) period
  std::vector<std::string> grids;
  std::vector<std::string> lines;
  WsjtxListener listener;

  explicit Rig(WsjtxConfig config = {})
      : listener{WsjtxParts{std::move(config), [this] { return now_s; },
                            [this] { return 1.7e9 + now_s; },
                            [this](const std::string& g) { grids.push_back(g); },
                            [this](const std::string& l) { lines.push_back(l); }}} {}
};

TEST(WsjtxListener, TheDxGridIsFollowedOncePerChange) {
  Rig r;
  r.listener.on_datagram(status("JO65MR", false));
  r.listener.on_datagram(status("JO65MR", false));
  ASSERT_EQ(r.grids.size(), 1U);
  EXPECT_EQ(r.grids[0], "JO65MR");
  EXPECT_EQ(r.listener.to_json()["dx_call"], "OZ1ABC");
}

TEST(WsjtxListener, TransmittingHoldsUntilAStatusACloseOrSilence) {
  Rig r;
  r.listener.on_datagram(status("", true));
  EXPECT_TRUE(r.listener.motion_hold());
  EXPECT_EQ(r.listener.to_json()["transmitting_since_unix_s"], 1.7e9 + 100.0);
  r.now_s += 5.0;
  r.listener.on_datagram(status("", true));  // still: the start is the first Status's receipt
  EXPECT_EQ(r.listener.to_json()["transmitting_since_unix_s"], 1.7e9 + 100.0);
  r.listener.on_datagram(status("", false));
  EXPECT_FALSE(r.listener.motion_hold());
  EXPECT_TRUE(r.listener.to_json()["transmitting_since_unix_s"].is_null());

  r.listener.on_datagram(status("", true));
  r.listener.on_datagram(header(6));  // Close
  EXPECT_FALSE(r.listener.transmitting());

  r.listener.on_datagram(status("", true));
  r.now_s += WsjtxListener::kStaleS - 1.0;
  EXPECT_TRUE(r.listener.transmitting());
  r.now_s += 2.0;  // WSJT-X died mid-transmission: no heartbeat for kStaleS
  EXPECT_FALSE(r.listener.transmitting());
  EXPECT_FALSE(r.listener.motion_hold());
}

TEST(WsjtxListener, MoveInLastSWorksInFt8ThoughItsStatusGivesNoPeriod) {
  WsjtxConfig config;
  config.move_in_last_s = 3.0;
  Rig r(config);
  r.listener.on_datagram(status("", false, "Q65"));  // Q65's period is the operator's: unknown
  EXPECT_TRUE(r.listener.to_json()["tr_period_s"].is_null());
  EXPECT_FALSE(r.listener.motion_hold()) << "no period: no window to wait for";
  r.listener.on_datagram(status("", false, "FT8"));
  EXPECT_EQ(r.listener.to_json()["tr_period_s"], 15.0);
  EXPECT_TRUE(r.listener.motion_hold()) << "0 s into the period";
  r.now_s += 11.9;
  EXPECT_TRUE(r.listener.motion_hold());
  r.now_s += 0.2;  // 12.1 s in: the last 3 s
  EXPECT_FALSE(r.listener.motion_hold());
  r.now_s += 2.8;  // 14.9 s
  EXPECT_FALSE(r.listener.motion_hold());
  r.now_s += 0.2;  // the next period
  EXPECT_TRUE(r.listener.motion_hold());
  r.listener.on_datagram(status("", false, "FT4"));
  EXPECT_EQ(r.listener.tr_period_s(), 7.5);
  r.now_s += 4.6;  // 4.7 s into a 7.5 s period: its last 3 s
  EXPECT_FALSE(r.listener.motion_hold());
  r.listener.on_datagram(status("", false, "Q65"));  // back to a mode that does not say
  EXPECT_EQ(r.listener.tr_period_s(), std::nullopt);
}

TEST(WsjtxListener, MalformedDatagramsAreCountedAndLoggedOnceAMinute) {
  Rig r;
  r.listener.on_datagram("garbage");
  r.listener.on_datagram(status("JO65", false).substr(0, 40));
  r.listener.on_oversized(9000);
  EXPECT_EQ(r.listener.malformed(), 3U);
  EXPECT_EQ(r.lines.size(), 1U);
  EXPECT_TRUE(r.grids.empty());
}

TEST(WsjtxListener, EachKindOfMessageIsCounted) {
  // What proves a real WSJT-X is heard (its heartbeats every 15 s, its Status on changes): the
  // counts in the state, beside the malformed ones.
  Rig r;
  r.listener.on_datagram(header(0));  // Heartbeat (ending after the id: schema 2's form)
  r.listener.on_datagram(status("", false));
  r.listener.on_datagram(status("", false));
  r.listener.on_datagram(header(2));  // a Decode: recognised, not read
  r.listener.on_datagram(header(6));  // Close
  r.listener.on_datagram("garbage");
  const nlohmann::json received = r.listener.to_json()["received"];
  EXPECT_EQ(received["heartbeat"], 1);
  EXPECT_EQ(received["status"], 2);
  EXPECT_EQ(received["close"], 1);
  EXPECT_EQ(received["other"], 1);
  EXPECT_EQ(r.listener.to_json()["malformed"], 1);
}

}  // namespace
}  // namespace azt::app
