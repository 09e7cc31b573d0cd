// The gpsd client against a stand-in gpsd on loopback (docs/gps.md): it asks for JSON, turns
// TPV and SKY reports into fixes and skies through libgps's parser, drops what is not a report,
// gives up on a line no gpsd would send, and finds gpsd again after it went away or before it
// started. The real gpsd fed by gpsfake is tests/integration/gps_test.py's.
#include "azt/linux/gpsd_client.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "run_until.hpp"

namespace azt::linux_os {
namespace {

namespace asio = boost::asio;
using asio::ip::tcp;

/// A gpsd that accepts one client at a time, keeps what it asked and sends what it is told.
struct FakeGpsd {
  asio::io_context& io;
  tcp::acceptor acceptor;
  std::unique_ptr<tcp::socket> client;
  std::string asked;
  std::array<char, 256> buffer{};

  explicit FakeGpsd(asio::io_context& io_, unsigned short port = 0)
      : io(io_), acceptor(io_, tcp::endpoint(asio::ip::make_address("127.0.0.1"), port)) {
    accept();
  }
  [[nodiscard]] unsigned short port() const { return acceptor.local_endpoint().port(); }
  void accept() {
    acceptor.async_accept([this](const boost::system::error_code& ec, tcp::socket s) {
      if (ec) return;
      client = std::make_unique<tcp::socket>(std::move(s));
      listen();
    });
  }
  void listen() {
    client->async_read_some(asio::buffer(buffer),
                            [this](const boost::system::error_code& ec, std::size_t n) {
                              if (ec) return;
                              asked.append(buffer.data(), n);
                              listen();
                            });
  }
  void send(const std::string& text) const { asio::write(*client, asio::buffer(text)); }
  void hang_up() {
    client->close();
    client.reset();
    accept();
  }
};

struct Seen {
  int connected = 0;
  std::vector<std::string> lost;
  std::vector<gnss::GpsFix> fixes;
  std::vector<gnss::GpsSky> skies;
  GpsdEvents events() {
    return {[this] { ++connected; }, [this](const std::string& why) { lost.push_back(why); },
            [this](const gnss::GpsFix& f) { fixes.push_back(f); },
            [this](const gnss::GpsSky& s) { skies.push_back(s); }};
  }
};

constexpr const char* kTpv3d =
    R"({"class":"TPV","device":"/dev/pts/1","mode":3,"time":"2025-03-14T00:00:07.000Z",)"
    R"("lat":46.189572667,"lon":-79.3937475,"altHAE":268.6,"altMSL":303.2,"speed":0.006})"
    "\n";
constexpr const char* kSky =
    R"({"class":"SKY","device":"/dev/pts/1","hdop":0.94,"nSat":3,"uSat":2,"satellites":[)"
    R"({"PRN":2,"el":67.0,"az":45.0,"ss":32.0,"used":true},)"
    R"({"PRN":5,"el":41.0,"az":120.0,"ss":35.0,"used":true},)"
    R"({"PRN":10,"el":5.0,"az":190.0,"ss":12.0,"used":false}]})"
    "\n";

GpsdClientConfig config_for(unsigned short port) {
  return {"127.0.0.1", std::to_string(port), 0.05};
}

TEST(GpsdClient, AsksForJsonAndDecodesTpvAndSky) {
  asio::io_context io;
  FakeGpsd gpsd(io);
  Seen seen;
  GpsdClient client(io, config_for(gpsd.port()), seen.events());
  ASSERT_TRUE(run_until(io, [&] { return seen.connected == 1 && gpsd.client != nullptr; }));
  ASSERT_TRUE(run_until(io, [&] { return gpsd.asked.find('\n') != std::string::npos; }));
  EXPECT_NE(gpsd.asked.find("?WATCH={\"enable\":true,\"json\":true}"), std::string::npos);
  gpsd.send(R"({"class":"VERSION","release":"3.22","proto_major":3,"proto_minor":14})"
            "\n");
  gpsd.send(kTpv3d);
  gpsd.send(kSky);
  ASSERT_TRUE(run_until(io, [&] { return !seen.fixes.empty() && !seen.skies.empty(); }));
  const gnss::GpsFix& f = seen.fixes.front();
  EXPECT_EQ(f.mode, gnss::FixMode::Fix3d);
  EXPECT_DOUBLE_EQ(f.lat_deg, 46.189572667);
  EXPECT_DOUBLE_EQ(f.lon_deg, -79.3937475);
  ASSERT_TRUE(f.alt_m.has_value());
  EXPECT_DOUBLE_EQ(*f.alt_m, 303.2);  // above mean sea level, not the ellipsoid
  ASSERT_TRUE(f.time_unix_s.has_value());
  EXPECT_DOUBLE_EQ(*f.time_unix_s, 1741910407.0);  // 2025-03-14T00:00:07Z
  const gnss::GpsSky& s = seen.skies.front();
  EXPECT_EQ(s.sats_visible, 3);
  EXPECT_EQ(s.sats_used, 2);
  ASSERT_TRUE(s.hdop.has_value());
  EXPECT_DOUBLE_EQ(*s.hdop, 0.94);
  ASSERT_EQ(s.satellites.size(), 3U);
  EXPECT_EQ(s.satellites[2].prn, 10);
  EXPECT_FALSE(s.satellites[2].used);
  EXPECT_DOUBLE_EQ(s.satellites[1].az_deg, 120.0);
  EXPECT_EQ(seen.fixes.size(), 1U) << "VERSION is not a fix";
}

TEST(GpsdClient, ANoFixTpvIsNoFixAndA2dFixHasNoAltitude) {
  asio::io_context io;
  FakeGpsd gpsd(io);
  Seen seen;
  GpsdClient client(io, config_for(gpsd.port()), seen.events());
  ASSERT_TRUE(run_until(io, [&] { return gpsd.client != nullptr; }));
  gpsd.send(R"({"class":"TPV","device":"/dev/pts/1","mode":1})"
            "\n");
  gpsd.send(R"({"class":"TPV","mode":2,"lat":46.0,"lon":-79.0,"altMSL":300.0})"
            "\n");
  ASSERT_TRUE(run_until(io, [&] { return seen.fixes.size() == 2; }));
  EXPECT_EQ(seen.fixes[0].mode, gnss::FixMode::None);
  EXPECT_EQ(seen.fixes[1].mode, gnss::FixMode::Fix2d);
  EXPECT_FALSE(seen.fixes[1].alt_m.has_value());
}

TEST(GpsdClient, LinesThatAreNotReportsAreDroppedAndCounted) {
  asio::io_context io;
  FakeGpsd gpsd(io);
  Seen seen;
  GpsdClient client(io, config_for(gpsd.port()), seen.events());
  ASSERT_TRUE(run_until(io, [&] { return gpsd.client != nullptr; }));
  gpsd.send("not json at all\n");
  gpsd.send(std::string("{\"class\":\"TPV\",\"mode\":\xff\xfe}\n"));
  gpsd.send("{\"class\":\n");
  gpsd.send(kTpv3d);
  ASSERT_TRUE(run_until(io, [&] { return !seen.fixes.empty(); }));
  EXPECT_EQ(seen.fixes.size(), 1U);
  EXPECT_GE(client.rejected_lines(), 2U);
  EXPECT_TRUE(client.connected());
  EXPECT_TRUE(seen.lost.empty());
}

TEST(GpsdClient, ALineNoGpsdWouldSendDropsTheLinkWhichComesBack) {
  asio::io_context io;
  FakeGpsd gpsd(io);
  Seen seen;
  GpsdClient client(io, config_for(gpsd.port()), seen.events());
  ASSERT_TRUE(run_until(io, [&] { return gpsd.client != nullptr; }));
  gpsd.send("{" + std::string(std::size_t{70} * 1024, 'x'));
  ASSERT_TRUE(run_until(io, [&] { return !seen.lost.empty(); }));
  EXPECT_NE(seen.lost.front().find("longer than"), std::string::npos) << seen.lost.front();
  gpsd.hang_up();
  ASSERT_TRUE(run_until(io, [&] { return seen.connected == 2 && gpsd.client != nullptr; }));
  gpsd.send(kTpv3d);
  ASSERT_TRUE(run_until(io, [&] { return !seen.fixes.empty(); }));
}

TEST(GpsdClient, GpsdGoneIsSaidOnceAndFoundAgainWhenItReturns) {
  asio::io_context io;
  unsigned short port = 0;
  Seen seen;
  std::optional<GpsdClient> client;
  {
    FakeGpsd gpsd(io);
    port = gpsd.port();
    client.emplace(io, config_for(port), seen.events());
    ASSERT_TRUE(run_until(io, [&] { return gpsd.client != nullptr; }));
    gpsd.send(kTpv3d);
    ASSERT_TRUE(run_until(io, [&] { return !seen.fixes.empty(); }));
  }  // gpsd stops: its socket and listener close
  ASSERT_TRUE(run_until(io, [&] { return !seen.lost.empty(); }));
  EXPECT_FALSE(client->connected());
  // Several retries find nothing listening: said once, not at every retry.
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
  run_until(io, [&] { return std::chrono::steady_clock::now() > until; });
  EXPECT_EQ(seen.lost.size(), 1U);
  FakeGpsd again(io, port);  // gpsd restarted on its port
  ASSERT_TRUE(run_until(io, [&] { return seen.connected == 2 && again.client != nullptr; }));
  again.send(kTpv3d);
  ASSERT_TRUE(run_until(io, [&] { return seen.fixes.size() == 2; }));
}

}  // namespace
}  // namespace azt::linux_os
