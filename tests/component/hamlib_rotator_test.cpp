// Component tests of the Hamlib adapter against a real peer: Debian's rotctld (Hamlib 4.5.4)
// serving its dummy rotator (-m 1), reached through Hamlib's NET rotctl backend (model 2). No
// mocks: the adapter, libhamlib and rotctld all run for real.
//
// rotctld -m 1 simulates a rotator turning at 360 degrees per minute (6 deg/s; DEG_PER_MS in
// Hamlib's rotators/dummy/rot_dummy.c) on each axis independently, starting at az 0, el 0, with
// limits az -180..180, el 0..90; it only advances its position when asked for it.

#include "azt/linux/hamlib_rotator.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace azt::linux_os {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::duration;
using std::chrono::milliseconds;

constexpr const char* kRotctld = "/usr/bin/rotctld";
constexpr double kToleranceDeg = 0.5;

double seconds_since(Clock::time_point start) {
  return duration<double>(Clock::now() - start).count();
}

/// Polls `done` every 20 ms until it holds or `timeout` passes; returns its last value.
bool wait_until(const std::function<bool()>& done, duration<double> timeout) {
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(timeout);
  while (!done()) {
    if (Clock::now() >= deadline) return done();
    std::this_thread::sleep_for(milliseconds(20));
  }
  return true;
}

sockaddr_in loopback(std::uint16_t port) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  return address;
}

/// A port nothing listens on right now: bind port 0 and ask the kernel which one it chose.
std::uint16_t free_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address = loopback(0);
  socklen_t length = sizeof(address);
  if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    if (fd >= 0) ::close(fd);
    return 0;
  }
  ::close(fd);
  return ntohs(address.sin_port);
}

bool accepts_connections(std::uint16_t port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return false;
  const sockaddr_in address = loopback(port);
  const bool ok = ::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) == 0;
  ::close(fd);
  return ok;
}

/// rotctld -m 1 as a child process, killed with the test (and with us, via PR_SET_PDEATHSIG).
class Rotctld {
 public:
  Rotctld() = default;
  Rotctld(const Rotctld&) = delete;
  Rotctld& operator=(const Rotctld&) = delete;
  ~Rotctld() { stop(SIGTERM); }

  /// Starts it on 127.0.0.1:port and waits (at most 5 s) until it accepts connections.
  bool start(std::uint16_t port) {
    std::vector<std::string> args = {
        kRotctld, "-m", "1", "-T", "127.0.0.1", "-t", std::to_string(port)};
    std::vector<char*> argv;
    argv.reserve(args.size() + 1);
    for (auto& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    const pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ == 0) exec_child(argv.data(), parent);  // async-signal-safe calls only
    if (pid_ < 0) return false;
    return wait_until([port] { return accepts_connections(port); }, duration<double>(5.0));
  }

  void stop(int signal_number) {
    if (pid_ <= 0) return;
    ::kill(pid_, signal_number);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }

 private:
  [[noreturn]] static void exec_child(char* const* argv, pid_t parent) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(126);
    const int null_fd = ::open("/dev/null", O_RDWR);
    if (null_fd >= 0) {
      ::dup2(null_fd, STDOUT_FILENO);
      ::dup2(null_fd, STDERR_FILENO);
    }
    ::execv(kRotctld, argv);
    ::_exit(127);
  }

  pid_t pid_ = -1;
};

HamlibConfig net_config(std::uint16_t port) {
  HamlibConfig config;
  config.model = 2;  // NET rotctl
  config.device = "127.0.0.1:" + std::to_string(port);
  config.poll_s = 0.1;
  return config;
}

bool near(const std::optional<HamlibRotator::Reading>& reading, double az_deg, double el_deg) {
  return reading && std::fabs(reading->az_deg - az_deg) <= kToleranceDeg &&
         std::fabs(reading->el_deg - el_deg) <= kToleranceDeg;
}

// ---- failures that need no peer ---------------------------------------------------------------

TEST(HamlibRotatorOpen, UnknownModelFailsNamingTheModel) {
  HamlibConfig config;
  config.model = 999999;
  const auto opened = HamlibRotator::open(config);
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.error().message.find("999999"), std::string::npos) << opened.error().message;
}

TEST(HamlibRotatorOpen, NothingListeningFailsCleanlyNamingTheAddress) {
  const std::uint16_t port = free_port();
  ASSERT_NE(port, 0);
  const auto start = Clock::now();
  const auto opened = HamlibRotator::open(net_config(port));
  ASSERT_FALSE(opened.ok());
  const std::string& message = opened.error().message;
  EXPECT_NE(message.find("127.0.0.1:" + std::to_string(port)), std::string::npos) << message;
  EXPECT_NE(message.find("rot_open"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line, not Hamlib's debug trail";
  EXPECT_LT(seconds_since(start), 3.0);
}

TEST(HamlibRotatorOpen, SerialSpeedOnANetworkModelIsRejected) {
  HamlibConfig config = net_config(free_port());
  config.baud = 9600;
  const auto opened = HamlibRotator::open(config);
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.error().message.find("serial_speed"), std::string::npos)
      << opened.error().message;
}

TEST(HamlibRotatorOpen, InvalidTimingIsRejected) {
  HamlibConfig config;
  config.poll_s = 0.0;
  EXPECT_FALSE(HamlibRotator::open(config).ok());
  config.poll_s = 0.2;
  config.min_move_deg = std::nan("");
  EXPECT_FALSE(HamlibRotator::open(config).ok());
}

TEST(HamlibRotatorOpen, InProcessDummyReportsItsStartPosition) {
  const auto opened = HamlibRotator::open(HamlibConfig{});  // model 1, no port
  ASSERT_TRUE(opened.ok()) << opened.error().message;
  const auto& rotator = opened.value();
  EXPECT_TRUE(rotator->connected());
  ASSERT_TRUE(wait_until([&] { return rotator->latest().has_value(); }, duration<double>(2.0)));
  EXPECT_TRUE(near(rotator->latest(), 0.0, 0.0));
}

// ---- against rotctld --------------------------------------------------------------------------

class HamlibRotatorRotctld : public ::testing::Test {
 protected:
  void SetUp() override {
    if (::access(kRotctld, X_OK) != 0) GTEST_SKIP() << kRotctld << " is not installed";
    port_ = free_port();
    ASSERT_NE(port_, 0);
    ASSERT_TRUE(rotctld_.start(port_)) << "rotctld did not accept connections within 5 s";
  }

  void TearDown() override {
    rotator_.reset();
    rotctld_.stop(SIGTERM);
  }

  void open(const HamlibConfig& config) {
    auto opened = HamlibRotator::open(config);
    ASSERT_TRUE(opened.ok()) << opened.error().message;
    rotator_ = std::move(opened).value();
    ASSERT_TRUE(
        wait_until([this] { return rotator_->latest().has_value(); }, duration<double>(2.0)));
  }

  /// Seconds until the reading is within kToleranceDeg of the target, or a negative number.
  double seconds_to_reach(double az_deg, double el_deg, double timeout_s = 10.0) {
    const auto start = Clock::now();
    if (!wait_until([&] { return near(rotator_->latest(), az_deg, el_deg); },
                    duration<double>(timeout_s))) {
      return -1.0;
    }
    return seconds_since(start);
  }

  std::uint16_t port_ = 0;
  Rotctld rotctld_;
  std::unique_ptr<HamlibRotator> rotator_;
};

TEST_F(HamlibRotatorRotctld, MovesToACommandedPosition) {
  open(net_config(port_));
  EXPECT_TRUE(rotator_->connected());
  EXPECT_TRUE(near(rotator_->latest(), 0.0, 0.0)) << "the dummy starts at az 0, el 0";
  rotator_->command_position(10.0, 5.0);
  const double took_s = seconds_to_reach(10.0, 5.0);
  ASSERT_GE(took_s, 0.0) << "reading: " << rotator_->latest()->az_deg << " "
                         << rotator_->latest()->el_deg << "; " << rotator_->last_error();
  std::printf("[ timing   ] az 0->10, el 0->5 reached in %.2f s\n", took_s);
  RecordProperty("move_0_0_to_10_5_s", std::to_string(took_s));
  EXPECT_GT(took_s, 1.0) << "the dummy turns at 6 deg/s: 10 degrees take about 1.7 s";
  EXPECT_TRUE(rotator_->last_error().empty()) << rotator_->last_error();
}

TEST_F(HamlibRotatorRotctld, ReadingsKeepComingAtThePollRate) {
  open(net_config(port_));
  const auto first = rotator_->latest()->at;
  std::this_thread::sleep_for(milliseconds(500));
  const auto later = rotator_->latest()->at;
  EXPECT_GT(later, first);
  EXPECT_LT(Clock::now() - later, milliseconds(300)) << "poll_s is 0.1";
}

TEST_F(HamlibRotatorRotctld, StopLeavesTheReadingStationary) {
  open(net_config(port_));
  rotator_->command_position(100.0, 40.0);
  ASSERT_TRUE(
      wait_until([this] { return rotator_->latest()->az_deg > 5.0; }, duration<double>(5.0)));
  rotator_->command_stop();
  std::this_thread::sleep_for(milliseconds(400));
  const auto stopped = *rotator_->latest();
  std::this_thread::sleep_for(milliseconds(1000));
  const auto later = *rotator_->latest();
  EXPECT_GT(later.at, stopped.at) << "still polling";
  EXPECT_NEAR(later.az_deg, stopped.az_deg, 0.01);
  EXPECT_NEAR(later.el_deg, stopped.el_deg, 0.01);
  EXPECT_LT(stopped.az_deg, 50.0) << "stopped well short of the target";
}

TEST_F(HamlibRotatorRotctld, PositionAfterAStopIsStillSent) {
  open(net_config(port_));
  rotator_->command_position(10.0, 5.0);
  ASSERT_GE(seconds_to_reach(10.0, 5.0), 0.0);
  rotator_->command_stop();
  rotator_->command_position(4.0, 2.0);  // commanded after the stop: goes out after it
  EXPECT_GE(seconds_to_reach(4.0, 2.0), 0.0);
}

TEST_F(HamlibRotatorRotctld, SetpointWithinMinMoveIsNotResent) {
  HamlibConfig config = net_config(port_);
  config.min_move_deg = 1.0;
  open(config);
  rotator_->command_position(10.0, 5.0);
  ASSERT_GE(seconds_to_reach(10.0, 5.0), 0.0);
  rotator_->command_position(10.6, 5.6);  // closer than 1 degree on both axes: not sent
  std::this_thread::sleep_for(milliseconds(800));
  EXPECT_NEAR(rotator_->latest()->az_deg, 10.0, 0.01);
  EXPECT_NEAR(rotator_->latest()->el_deg, 5.0, 0.01);
  rotator_->command_position(12.0, 5.0);  // 2 degrees away: sent
  EXPECT_GE(seconds_to_reach(12.0, 5.0), 0.0);
}

TEST_F(HamlibRotatorRotctld, NonFiniteSetpointIsIgnoredAndReported) {
  open(net_config(port_));
  rotator_->command_position(std::nan(""), 5.0);
  rotator_->command_position(10.0, HUGE_VAL);
  EXPECT_NE(rotator_->last_error().find("non-finite"), std::string::npos);
  std::this_thread::sleep_for(milliseconds(500));
  EXPECT_TRUE(near(rotator_->latest(), 0.0, 0.0));
  EXPECT_TRUE(rotator_->connected());
}

TEST_F(HamlibRotatorRotctld, OutOfRangeSetpointIsRejectedWithoutDroppingTheLink) {
  open(net_config(port_));
  rotator_->command_position(720.0, 5.0);  // beyond any az limit Hamlib knows
  ASSERT_TRUE(
      wait_until([this] { return !rotator_->last_error().empty(); }, duration<double>(2.0)));
  EXPECT_NE(rotator_->last_error().find("rot_set_position"), std::string::npos)
      << rotator_->last_error();
  EXPECT_TRUE(rotator_->connected());
  rotator_->command_position(10.0, 5.0);
  EXPECT_GE(seconds_to_reach(10.0, 5.0), 0.0);
}

TEST_F(HamlibRotatorRotctld, ReconnectsAfterRotctldIsKilledAndRestarted) {
  open(net_config(port_));
  ASSERT_TRUE(rotator_->connected());

  rotctld_.stop(SIGKILL);
  const auto killed_at = Clock::now();
  ASSERT_TRUE(wait_until([this] { return !rotator_->connected(); }, duration<double>(15.0)))
      << "still connected " << seconds_since(killed_at) << " s after rotctld died";
  const double detect_s = seconds_since(killed_at);
  EXPECT_FALSE(rotator_->last_error().empty());
  std::printf("[ timing   ] link loss detected %.2f s after kill -9: %s\n", detect_s,
              rotator_->last_error().c_str());

  ASSERT_TRUE(rotctld_.start(port_)) << "could not restart rotctld on the same port";
  const auto restarted_at = Clock::now();
  ASSERT_TRUE(
      wait_until([&] { return rotator_->connected() && rotator_->latest()->at > restarted_at; },
                 duration<double>(10.0)))
      << rotator_->last_error();
  std::printf("[ timing   ] reconnected %.2f s after restart\n", seconds_since(restarted_at));
  rotator_->command_position(10.0, 5.0);
  EXPECT_GE(seconds_to_reach(10.0, 5.0), 0.0) << rotator_->last_error();
}

TEST_F(HamlibRotatorRotctld, SetpointCommandedWhileDisconnectedIsSentAfterReconnect) {
  open(net_config(port_));
  rotctld_.stop(SIGKILL);
  ASSERT_TRUE(wait_until([this] { return !rotator_->connected(); }, duration<double>(15.0)));
  rotator_->command_position(10.0, 5.0);
  ASSERT_TRUE(rotctld_.start(port_));
  EXPECT_GE(seconds_to_reach(10.0, 5.0, 15.0), 0.0) << rotator_->last_error();
}

TEST_F(HamlibRotatorRotctld, DestructionIsPromptWhileConnectedAndWhileReconnecting) {
  open(net_config(port_));
  auto start = Clock::now();
  rotator_.reset();
  EXPECT_LT(seconds_since(start), 1.0);

  open(net_config(port_));
  rotctld_.stop(SIGKILL);
  ASSERT_TRUE(wait_until([this] { return !rotator_->connected(); }, duration<double>(15.0)));
  start = Clock::now();
  rotator_.reset();
  EXPECT_LT(seconds_since(start), 1.0) << "the reconnect back-off must be interruptible";
}

}  // namespace
}  // namespace azt::linux_os
