#pragma once
// The `pwm` backend's hardware, faked for the station's tests: a /sys/class/pwm chip laid out as
// the kernel lays it out (export, pwm0..3 with period, duty_cycle, enable), and an EncoderHub on
// a pseudo-terminal whose master end the test writes frames to.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "azt/proto/hub_frame.hpp"

namespace azt::app::testing {

class FakePwmStation {
 public:
  /// Makes the tree under the temp directory, named `name` and the process id; `open_flags` add
  /// to the master's (O_NONBLOCK for a loop that must never wait on it).
  void make(const std::string& name, int open_flags = 0) {
    namespace fs = std::filesystem;
    dir_ = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "pwmchip0");
    std::ofstream(dir_ / "pwmchip0" / "export") << "";
    for (int ch = 0; ch < 4; ++ch) {
      const fs::path p = dir_ / "pwmchip0" / ("pwm" + std::to_string(ch));
      fs::create_directories(p);
      for (const char* f : {"period", "duty_cycle", "enable"}) std::ofstream(p / f) << "0";
    }
    master_ = posix_openpt(O_RDWR | O_NOCTTY | open_flags);
    ASSERT_GE(master_, 0);
    ASSERT_EQ(grantpt(master_), 0);
    ASSERT_EQ(unlockpt(master_), 0);
    std::array<char, 128> pts{};
    ASSERT_EQ(ptsname_r(master_, pts.data(), pts.size()), 0);
    fs::create_symlink(pts.data(), dir_ / "hub");
  }
  void remove() {
    close_hub();
    std::filesystem::remove_all(dir_);
  }
  void close_hub() {
    if (master_ >= 0) ::close(master_);
    master_ = -1;
  }

  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }
  [[nodiscard]] int master() const { return master_; }
  /// The [hub] and [pwm] tables for this tree.
  [[nodiscard]] std::string config_tables() const {
    return "[hub]\ndevice = \"" + (dir_ / "hub").string() + "\"\n[pwm]\nchip = \"" +
           (dir_ / "pwmchip0").string() + "\"\n";
  }
  /// One CRC frame with 12-bit readings of these angles.
  void send_frame(double az_deg, double el_deg) const {
    send_reading(proto::HubReading{12, 12, static_cast<std::uint16_t>(az_deg / 360.0 * 4096.0),
                                   static_cast<std::uint16_t>(el_deg / 360.0 * 4096.0)});
  }
  /// Any reading, an axis error among them, as a CRC-8 frame.
  void send_reading(const proto::HubReading& r) const {
    std::array<std::uint8_t, 32> out{};
    const auto n = proto::encode_hub_frame(r, proto::HubFrameVersion::Crc8, out.data(), out.size());
    ASSERT_GT(n, 0U);
    ASSERT_EQ(::write(master_, out.data(), n), static_cast<ssize_t>(n));
  }
  /// A channel's attribute as text ("0", "1", a duty in ns).
  [[nodiscard]] std::string attribute(int channel, const char* name) const {
    std::ifstream in(dir_ / "pwmchip0" / ("pwm" + std::to_string(channel)) / name);
    std::string v;
    in >> v;
    return v;
  }
  [[nodiscard]] std::uint64_t duty(int channel) const {
    const std::string v = attribute(channel, "duty_cycle");
    return v.empty() ? 0 : std::stoull(v);
  }

 private:
  std::filesystem::path dir_;
  int master_ = -1;
};

}  // namespace azt::app::testing
