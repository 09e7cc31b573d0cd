// The network links for the console (docs/network.md): the reading off the loop becomes `network`,
// and a link going down or coming back is logged once, not at every look.
#include "station/network_watch.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace azt::app {
namespace {

linux_os::NetworkInterface wlan0(bool up) {
  linux_os::NetworkInterface n;
  n.name = "wlan0";
  n.kind = linux_os::LinkKind::Wifi;
  n.operstate = up ? "up" : "down";
  n.up = up;
  n.carrier = up;
  n.mac = "b8:27:eb:00:00:02";
  n.addresses = {"192.168.1.20/24"};
  n.wifi = linux_os::WifiLink{std::string("shack-net"), -56.0, 88};
  return n;
}

TEST(NetworkWatch, TheLinksAreShownAndChangesLoggedOnce) {
  boost::asio::io_context io;
  NetworkReading reading{{wlan0(true)}, true};
  std::vector<std::string> log;
  NetworkWatch watch(io, NetworkWatchParts{5.0, run_inline, [&] { return reading; },
                                           [&](const std::string& l) { log.push_back(l); }});
  auto j = watch.to_json();
  EXPECT_EQ(j["networkmanager"], true);
  ASSERT_EQ(j["interfaces"].size(), 1U);
  const auto& w = j["interfaces"][0];
  EXPECT_EQ(w["name"], "wlan0");
  EXPECT_EQ(w["kind"], "wifi");
  EXPECT_EQ(w["up"], true);
  EXPECT_EQ(w["speed_mbps"], nullptr);
  EXPECT_EQ(w["addresses"], nlohmann::json({"192.168.1.20/24"}));
  EXPECT_EQ(w["wifi"]["ssid"], "shack-net");
  EXPECT_EQ(w["wifi"]["signal_percent"], 88);
  EXPECT_TRUE(log.empty()) << "a link up at start is not news";

  reading.interfaces = {wlan0(false)};
  watch.check_now();
  watch.check_now();
  ASSERT_EQ(log.size(), 1U);
  EXPECT_EQ(log[0], "network: wlan0 link down (down)");
  reading.interfaces = {wlan0(true)};
  watch.check_now();
  ASSERT_EQ(log.size(), 2U);
  EXPECT_EQ(log[1], "network: wlan0 link up (up)");
  EXPECT_EQ(watch.to_json()["interfaces"][0]["up"], true);
}

}  // namespace
}  // namespace azt::app
