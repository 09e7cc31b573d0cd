// The station's network links (docs/network.md): interfaces read from a sysfs tree laid out as the
// kernel's (Ethernet with a device, WiFi, a bridge, loopback left out), the WiFi signal from
// /proc/net/wireless, and the SSID from a stand-in NetworkManager on a private D-Bus.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "azt/linux/network_interfaces.hpp"
#include "azt/linux/networkmanager_wifi.hpp"

extern char** environ;  // NOLINT(readability-redundant-declaration): POSIX, for posix_spawnp

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text << "\n";
}

class NetworkTree : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("azt-net-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    const fs::path net = root_ / "net";
    link(net / "eth0", "1", "up", "1", "b8:27:eb:00:00:01", "1000");
    fs::create_directories(net / "eth0" / "device");
    link(net / "wlan0", "1", "up", "1", "b8:27:eb:00:00:02", "-1");
    fs::create_directories(net / "wlan0" / "wireless");
    link(net / "br0", "1", "down", "", "02:00:00:00:00:03", "");
    link(net / "lo", "772", "unknown", "1", "00:00:00:00:00:00", "");
    write(root_ / "wireless",
          "Inter-| sta-|   Quality        |   Discarded packets               | Missed | WE\n"
          " face | tus | link level noise |  nwid  crypt   frag  retry   misc | beacon | 22\n"
          " wlan0: 0000   54.  -56.  -256        0      0      0      0      0        0");
  }
  void TearDown() override { fs::remove_all(root_); }

  static void link(const fs::path& dir, const std::string& type, const std::string& operstate,
                   const std::string& carrier, const std::string& mac, const std::string& speed) {
    write(dir / "type", type);
    write(dir / "operstate", operstate);
    if (!carrier.empty()) write(dir / "carrier", carrier);
    write(dir / "address", mac);
    if (!speed.empty()) write(dir / "speed", speed);
  }

  NetworkPaths paths() const { return {(root_ / "net").string(), (root_ / "wireless").string()}; }

  fs::path root_;
};

TEST_F(NetworkTree, EachLinkIsReadLoopbackLeftOut) {
  const auto links = read_network_interfaces(paths());
  ASSERT_EQ(links.size(), 3U);
  const NetworkInterface& br0 = links[0];
  const NetworkInterface& eth0 = links[1];
  const NetworkInterface& wlan0 = links[2];
  EXPECT_EQ(br0.name, "br0");
  EXPECT_EQ(br0.kind, LinkKind::Other) << "an Ethernet-type interface without a device";
  EXPECT_FALSE(br0.up);
  EXPECT_FALSE(br0.carrier.has_value()) << "carrier cannot be read while down";
  EXPECT_EQ(eth0.kind, LinkKind::Ethernet);
  EXPECT_TRUE(eth0.up);
  EXPECT_EQ(eth0.carrier, true);
  EXPECT_EQ(eth0.mac, "b8:27:eb:00:00:01");
  EXPECT_EQ(eth0.speed_mbps, 1000);
  EXPECT_FALSE(eth0.wifi.has_value());
  EXPECT_EQ(wlan0.kind, LinkKind::Wifi);
  EXPECT_FALSE(wlan0.speed_mbps.has_value()) << "-1: the driver does not say";
  ASSERT_TRUE(wlan0.wifi.has_value());
  EXPECT_EQ(wlan0.wifi->signal_dbm, -56.0);
  EXPECT_EQ(wlan0.wifi->signal_percent, 88);
  EXPECT_FALSE(wlan0.wifi->ssid.has_value()) << "sysfs does not know the SSID";
}

TEST_F(NetworkTree, AMissingTreeIsNoLinksNotACrash) {
  EXPECT_TRUE(read_network_interfaces({"/nonexistent/net", "/nonexistent/wireless"}).empty());
}

TEST(SignalPercent, NetworkManagersScale) {
  EXPECT_EQ(signal_percent_from_dbm(-100.0), 0);
  EXPECT_EQ(signal_percent_from_dbm(-50.0), 100);
  EXPECT_EQ(signal_percent_from_dbm(-75.0), 50);
  EXPECT_EQ(signal_percent_from_dbm(-120.0), 0);
  EXPECT_EQ(signal_percent_from_dbm(-20.0), 100);
}

TEST(SystemNetworkInterfaces, TheMachinesOwnLinksAreRead) {
  // Whatever this machine has: never loopback, and every name is a real interface.
  for (const auto& n : read_network_interfaces()) {
    EXPECT_NE(n.name, "lo");
    EXPECT_TRUE(fs::exists("/sys/class/net/" + n.name)) << n.name;
  }
}

/// A private bus (dbus-daemon) with the stand-in NetworkManager on it, as the system bus.
class StandInNetworkManager : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("azt-nm-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    address_ = "unix:path=" + (dir_ / "bus").string();
    const std::string& address = address_;
    write(dir_ / "bus.conf",
          "<!DOCTYPE busconfig PUBLIC \"-//freedesktop//DTD D-Bus Bus Configuration 1.0//EN\"\n"
          " \"http://www.freedesktop.org/standards/dbus/1.0/busconfig.dtd\">\n"
          "<busconfig><type>session</type><listen>" +
              address +
              "</listen><auth>EXTERNAL</auth><policy context=\"default\"><allow "
              "send_destination=\"*\"/><allow receive_sender=\"*\"/><allow "
              "own=\"*\"/></policy></busconfig>");
    bus_ = spawn({"dbus-daemon", "--nofork", "--config-file=" + (dir_ / "bus.conf").string()});
    ::setenv("DBUS_SYSTEM_BUS_ADDRESS", address.c_str(), 1);
    // The bus listens once its socket exists: from then on "no answer" means no NetworkManager.
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!fs::exists(dir_ / "bus") && std::chrono::steady_clock::now() < end) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  void TearDown() override {
    for (const pid_t pid : {nm_, bus_}) {
      if (pid <= 0) continue;
      ::kill(pid, SIGTERM);
      ::waitpid(pid, nullptr, 0);
    }
    ::unsetenv("DBUS_SYSTEM_BUS_ADDRESS");
    fs::remove_all(dir_);
  }

  static pid_t spawn(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));  // NOLINT: POSIX
    args.push_back(nullptr);
    pid_t pid = 0;
    return ::posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ) == 0 ? pid : -1;
  }

  void start_network_manager() {
    nm_ = spawn({"/usr/bin/python3", AZT_SOURCE_DIR "/tests/data/network/fake_networkmanager.py",
                 address_});
  }

  /// Asks until NetworkManager answers (it takes a moment to start), at most 20 s.
  static std::optional<std::map<std::string, WifiLink>> until_answered() {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (std::chrono::steady_clock::now() < end) {
      if (auto links = read_networkmanager_wifi()) return links;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return std::nullopt;
  }

  fs::path dir_;
  std::string address_;
  pid_t bus_ = -1;
  pid_t nm_ = -1;
};

TEST_F(StandInNetworkManager, TheSsidAndSignalOfEachWifiLink) {
  ASSERT_GT(bus_, 0) << "dbus-daemon did not start";
  start_network_manager();
  const auto links = until_answered();
  ASSERT_TRUE(links.has_value()) << "the stand-in NetworkManager never answered";
  EXPECT_EQ(links->count("eth0"), 0U) << "Ethernet has no SSID";
  ASSERT_EQ(links->count("wlan0"), 1U);
  EXPECT_EQ(links->at("wlan0").ssid, "shack-net");
  EXPECT_EQ(links->at("wlan0").signal_percent, 72);
  ASSERT_EQ(links->count("wlan1"), 1U);
  EXPECT_FALSE(links->at("wlan1").ssid.has_value()) << "not associated";
}

TEST_F(StandInNetworkManager, NoNetworkManagerOnTheBusIsNone) {
  ASSERT_TRUE(bus_ > 0 && fs::exists(dir_ / "bus")) << "dbus-daemon did not start";
  // The bus answers (a private bus is up within moments) but nobody owns NetworkManager's name.
  EXPECT_FALSE(read_networkmanager_wifi().has_value());
  ::setenv("DBUS_SYSTEM_BUS_ADDRESS", "unix:path=/nonexistent/bus", 1);
  EXPECT_FALSE(read_networkmanager_wifi().has_value()) << "no bus at all";
}

}  // namespace
}  // namespace azt::linux_os
