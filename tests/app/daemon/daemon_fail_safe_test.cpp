// Every way out of the daemon leaves the outputs safe (docs/daemon.md, "Failing safe"): the real
// `serve` loop on the `pwm` backend, driving a fake /sys/class/pwm chip from EncoderHub frames on a
// pseudo-terminal, moved by a rotctld client. Once the azimuth bridge is driven, an exception
// thrown from a handler, or a SIGTERM, must leave every duty at 0 and every channel disabled.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "azt/linux/asio.hpp"
#include "config/config_store.hpp"
#include "daemon/daemon.hpp"
#include "support/fake_pwm_station.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;
namespace asio = boost::asio;

unsigned short free_port() {
  asio::io_context io;
  asio::ip::tcp::acceptor a(io, asio::ip::tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  return a.local_endpoint().port();
}

class DaemonFailSafeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    station_.make("azt_fail_safe", O_NONBLOCK);
    port_ = free_port();
    std::ofstream(dir() / "azeltrack.toml")
        << "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"pwm\"\n"
        << station_.config_tables()
        << "[sim.az]\nencoder_bits = 12\nstart_deg = 180.0\n"
           "[sim.el]\nencoder_bits = 12\nstart_deg = 10.0\n[target]\nname = \"stop\"\n"
           "[rotctld]\nport = "
        << port_ << "\n[pstrotator]\nport = 0\n[web]\nport = 0\n";
  }
  void TearDown() override { station_.remove(); }
  [[nodiscard]] const fs::path& dir() const { return station_.dir(); }

  [[nodiscard]] std::string file(int channel, const char* name) const {
    return station_.attribute(channel, name);
  }

  /// Runs the daemon: hub frames every 20 ms (the antenna stays at 180°), a rotctld client asks
  /// for 200°; once the azimuth bridge drives, `fault` runs on the loop. Returns the exit code.
  int run_until_driven_then(const std::function<void()>& fault) {
    ConfigStore store = ConfigStore::open((dir() / "azeltrack.toml").string());
    DaemonOptions options;
    options.config_path = (dir() / "azeltrack.toml").string();
    options.run_for_s = 15.0;  // a bound, never reached when the test passes
    options.on_loop_started = [this, fault](asio::io_context& io) {
      EXPECT_EQ(::write(station_.master(), "\0", 1), 1);
      auto client = std::make_shared<asio::ip::tcp::socket>(io);
      client->connect({asio::ip::make_address("127.0.0.1"), port_});
      asio::write(*client, asio::buffer(std::string("P 200 10\n")));
      auto timer = std::make_shared<asio::steady_timer>(io);
      auto step = std::make_shared<std::function<void()>>();
      *step = [this, timer, step, client, fault] {
        send_frame();
        if (file(0, "duty_cycle") != "0" || file(1, "duty_cycle") != "0") {
          driven_ = true;
          fault();
          return;
        }
        timer->expires_after(std::chrono::milliseconds(20));
        timer->async_wait([step](boost::system::error_code ec) {
          if (!ec) (*step)();
        });
      };
      (*step)();
    };
    return run_daemon(store, options);
  }

  void send_frame() const { station_.send_frame(180.0, 10.0); }

  void expect_every_output_safe() const {
    for (int ch = 0; ch < 4; ++ch) {
      EXPECT_EQ(file(ch, "duty_cycle"), "0") << "pwm" << ch << " still has a duty";
      EXPECT_EQ(file(ch, "enable"), "0") << "pwm" << ch << " still enabled";
    }
  }

  testing::FakePwmStation station_;
  unsigned short port_ = 0;
  bool driven_ = false;
};

TEST_F(DaemonFailSafeTest, AnExceptionFromAHandlerStopsEveryOutputAndExits1) {
  const int code = run_until_driven_then([] { throw std::runtime_error("injected fault"); });
  ASSERT_TRUE(driven_) << "the azimuth bridge was never driven";
  EXPECT_EQ(code, 1);
  expect_every_output_safe();
}

TEST_F(DaemonFailSafeTest, SigtermStopsEveryOutputAndExits0) {
  const int code = run_until_driven_then([] { ::kill(::getpid(), SIGTERM); });
  ASSERT_TRUE(driven_) << "the azimuth bridge was never driven";
  EXPECT_EQ(code, 0);
  expect_every_output_safe();
}

}  // namespace
}  // namespace azt::app
