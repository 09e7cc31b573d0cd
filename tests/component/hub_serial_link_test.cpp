// The EncoderHub serial link against pseudo-terminals: frames in, a corrupt byte
// rejected, the adapter unplugged (the terminal closed) and plugged back in at the same path.
#include "azt/linux/hub_serial_link.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <vector>

#include "run_until.hpp"

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

/// A pseudo-terminal whose slave is reached through a symbolic link, like /dev/serial/by-id/.
struct FakeAdapter {
  int master = -1;
  void plug(const fs::path& link) {
    master = posix_openpt(O_RDWR | O_NOCTTY);
    ASSERT_GE(master, 0);
    ASSERT_EQ(grantpt(master), 0);
    ASSERT_EQ(unlockpt(master), 0);
    std::array<char, 128> name{};
    ASSERT_EQ(ptsname_r(master, name.data(), name.size()), 0);
    std::error_code ec;
    fs::remove(link, ec);
    fs::create_symlink(name.data(), link);
  }
  void unplug() {
    ::close(master);
    master = -1;
  }
  void send(const std::vector<std::uint8_t>& bytes) const {
    ASSERT_EQ(::write(master, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
  }
  ~FakeAdapter() {
    if (master >= 0) ::close(master);
  }
};

std::vector<std::uint8_t> frame(std::uint16_t az, std::uint16_t el) {
  std::array<std::uint8_t, 32> out{};
  const auto n = proto::encode_hub_frame(proto::HubReading{12, 12, az, el},
                                         proto::HubFrameVersion::Crc8, out.data(), out.size());
  return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n)};
}

TEST(HubSerialLink, FramesInUnplugAndReplug) {
  const fs::path dir = fs::temp_directory_path() / ("azt_hub_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path link = dir / "hub";
  FakeAdapter adapter;
  adapter.plug(link);
  boost::asio::io_context io;
  std::vector<proto::HubReading> readings;
  std::vector<std::string> events;
  HubSerialConfig config;
  config.device = link.string();
  config.retry_s = 0.05;
  auto hub = HubSerialLink::open(
      io, config, [&](const proto::HubFrame& f) { readings.push_back(f.reading); },
      [&](const std::string& e) { events.push_back(e); });
  ASSERT_TRUE(hub.ok()) << hub.error().message;

  adapter.send({0x00});  // the first delimiter: in sync from here
  adapter.send(frame(100, 200));
  auto corrupt = frame(300, 400);
  corrupt[3] ^= 0x10U;  // one flipped bit: the CRC rejects it
  adapter.send(corrupt);
  adapter.send(frame(500, 600));
  ASSERT_TRUE(run_until(io, [&] { return readings.size() >= 2; }));
  EXPECT_EQ(readings[0].az_raw, 100);
  EXPECT_EQ(readings[1].az_raw, 500);
  EXPECT_EQ(hub.value()->counters().bad_crc, 1U);

  // Unplugged in the middle of a frame: reported, then back at the same path.
  const auto half = frame(700, 800);
  adapter.send({half.begin(), half.begin() + 3});
  adapter.unplug();
  ASSERT_TRUE(run_until(io, [&] { return !events.empty(); }));
  EXPECT_NE(events[0].find("lost"), std::string::npos) << events[0];
  EXPECT_FALSE(hub.value()->connected());
  adapter.plug(link);
  ASSERT_TRUE(run_until(io, [&] { return hub.value()->connected(); }));
  adapter.send({0x00});
  adapter.send(frame(900, 1000));
  ASSERT_TRUE(run_until(io, [&] { return readings.size() >= 3; }));
  EXPECT_EQ(readings[2].az_raw, 900);  // the cut frame was not glued to the new one
  EXPECT_EQ(readings.size(), 3U);
  hub.value()->close();
  fs::remove_all(dir);
}

TEST(HubSerialLink, AMissingDeviceAtStartIsAClearError) {
  boost::asio::io_context io;
  HubSerialConfig config;
  config.device = "/dev/azeltrack-no-such-adapter";
  auto hub = HubSerialLink::open(io, config, nullptr, nullptr);
  ASSERT_FALSE(hub.ok());
  EXPECT_NE(hub.error().message.find("/dev/azeltrack-no-such-adapter"), std::string::npos);
}

}  // namespace
}  // namespace azt::linux_os
