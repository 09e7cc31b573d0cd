// Component tests of the libhamlib rig adapter (azt/linux/hamlib_rig.hpp) with real libhamlib
// 4.5.4 and no mocks: its in-process dummy rig (model 1), a serial model on a device that does not
// exist, and Debian's rigctld (-m 1) reached through Hamlib's NET rigctl backend (model 2), killed
// and started again. The loop is a real Asio loop; the adapter's worker thread makes the calls.

#include "azt/linux/hamlib_rig.hpp"
#include "azt/linux/hamlib_rig_model.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "run_until.hpp"

namespace azt::linux_os {
namespace {

using Clock = std::chrono::steady_clock;
using radio::RigCommand;
using radio::RigEvent;
using radio::RigEventKind;

constexpr const char* kRigctld = "/usr/bin/rigctld";

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// What the adapter told the loop.
struct Heard {
  std::vector<std::pair<RigLinkState, std::string>> links;
  std::vector<RigEvent> events;

  RigLinkEvents callbacks() {
    return {[this](RigLinkState s, const std::string& why) { links.emplace_back(s, why); },
            [this](const RigEvent& e) { events.push_back(e); }};
  }
  [[nodiscard]] std::size_t count(RigEventKind kind) const {
    return static_cast<std::size_t>(std::count_if(
        events.begin(), events.end(), [kind](const RigEvent& e) { return e.kind == kind; }));
  }
  [[nodiscard]] std::size_t downs() const {
    return static_cast<std::size_t>(std::count_if(
        links.begin(), links.end(), [](const auto& l) { return l.first == RigLinkState::Down; }));
  }
};

/// A timer every 10 ms on the loop, keeping the worst lateness: the loop never waits on the rig.
class LoopWatch {
 public:
  explicit LoopWatch(boost::asio::io_context& io) : timer_(io) { arm(); }
  [[nodiscard]] double worst_late_s() const { return worst_late_s_; }

 private:
  static constexpr auto kPeriod = std::chrono::milliseconds(10);
  void arm() {
    due_ = Clock::now() + kPeriod;
    timer_.expires_at(due_);
    timer_.async_wait([this](const boost::system::error_code& ec) {
      if (ec) return;
      worst_late_s_ = std::max(worst_late_s_, seconds_since(due_));
      arm();
    });
  }
  boost::asio::steady_timer timer_;
  Clock::time_point due_;
  double worst_late_s_ = 0.0;
};

/// Runs the loop until `done` or `limit_s` pass.
template <typename Done>
bool run_for_until(boost::asio::io_context& io, double limit_s, Done done) {
  const auto end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(limit_s));
  while (!done() && Clock::now() < end) {
    io.run_for(std::chrono::milliseconds(10));
    io.restart();
  }
  return done();
}

HamlibRigOptions quick_retries() {
  HamlibRigOptions o;
  o.retry_s = 0.05;
  o.max_retry_s = 0.2;
  o.idle_check_s = 0.2;
  return o;
}

std::uint16_t free_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof(address);
  if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    if (fd >= 0) ::close(fd);
    return 0;
  }
  ::close(fd);
  return ntohs(address.sin_port);
}

/// rigctld -m 1 on 127.0.0.1:port, killed with the test (and with us: PR_SET_PDEATHSIG).
class Rigctld {
 public:
  explicit Rigctld(std::uint16_t port) : port_(std::to_string(port)) {}
  Rigctld(const Rigctld&) = delete;
  Rigctld& operator=(const Rigctld&) = delete;
  ~Rigctld() { stop(); }

  void start() {
    std::vector<std::string> args = {kRigctld, "-m", "1", "-T", "127.0.0.1", "-t", port_};
    std::vector<char*> argv;
    for (auto& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    const pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(126);
      const int null_fd = ::open("/dev/null", O_RDWR);
      if (null_fd >= 0) {
        ::dup2(null_fd, STDOUT_FILENO);
        ::dup2(null_fd, STDERR_FILENO);
      }
      ::execv(kRigctld, argv.data());
      ::_exit(127);
    }
  }
  void stop() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }

 private:
  std::string port_;
  pid_t pid_ = -1;
};

TEST(HamlibRig, TheDummyRigTakesBothLegsAndAnswersInTheOrderAsked) {
  boost::asio::io_context io;
  Heard heard;
  HamlibRig rig(io, HamlibRigConfig{1, "", 0}, quick_retries(), heard.callbacks());
  EXPECT_FALSE(rig.set_rx_hz(145e6)) << "nothing is queued before the rig is open";
  ASSERT_TRUE(run_until(io, [&] { return rig.up(); })) << rig.down_reason();
  EXPECT_EQ(heard.links.size(), 1U);
  EXPECT_FALSE(rig.set_rx_hz(std::nan(""))) << "not a frequency";
  ASSERT_TRUE(rig.set_rx_hz(145800123.4));
  ASSERT_TRUE(rig.set_tx_hz(437800456.0));
  rig.flush();
  ASSERT_TRUE(run_until(io, [&] { return heard.count(RigEventKind::TxRead) == 1; }));
  ASSERT_EQ(heard.events.size(), 5U);
  const std::vector<std::pair<RigEventKind, RigCommand>> order = {
      {RigEventKind::Written, RigCommand::SetFreq},
      {RigEventKind::RxRead, RigCommand::GetFreq},
      {RigEventKind::Written, RigCommand::SetSplit},
      {RigEventKind::Written, RigCommand::SetSplitFreq},
      {RigEventKind::TxRead, RigCommand::GetSplitFreq}};
  for (std::size_t i = 0; i < order.size(); ++i) {
    EXPECT_EQ(heard.events[i].kind, order[i].first) << i;
    EXPECT_EQ(heard.events[i].command, order[i].second) << i;
  }
  EXPECT_DOUBLE_EQ(heard.events[1].hz, 145800123.0) << "whole Hz, read back from the rig";
  EXPECT_DOUBLE_EQ(heard.events[4].hz, 437800456.0);

  // The dial alone; split is not set twice on one connection.
  ASSERT_TRUE(rig.read_rx());
  ASSERT_TRUE(rig.set_tx_hz(437800999.0));
  rig.flush();
  // One turn carries both: the split leg first, then the dial, as rigctld's session sends them.
  ASSERT_TRUE(run_until(io, [&] {
    return heard.count(RigEventKind::TxRead) == 2 && heard.count(RigEventKind::RxRead) == 2;
  }));
  EXPECT_EQ(heard.events.size(), 8U) << "set_split_freq, get_split_freq and get_freq only";
  EXPECT_EQ(heard.count(RigEventKind::Refused), 0U);
}

TEST(HamlibRig, AMissingDeviceShowsItsReasonAndTheLoopRunsOnWhileRigOpenWaits) {
  boost::asio::io_context io;
  LoopWatch watch(io);
  Heard heard;
  const auto start = Clock::now();
  // The FT-817 (model 1020), a serial rig: Hamlib 4.5.4 tries its missing port for 2 s.
  HamlibRig rig(io, HamlibRigConfig{1020, "/nonexistent/azt-rig-tty", 0}, quick_retries(),
                heard.callbacks());
  EXPECT_EQ(rig.state(), RigLinkState::Connecting);
  ASSERT_TRUE(run_for_until(io, 10.0, [&] { return rig.state() == RigLinkState::Down; }));
  const double open_s = seconds_since(start);
  const std::string& why = rig.down_reason();
  EXPECT_NE(why.find("rig_open of model 1020 (Yaesu FT-817) at /nonexistent/azt-rig-tty failed"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("Hamlib status"), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << "one line, not Hamlib's debug trail";
  EXPECT_FALSE(rig.set_rx_hz(145e6));
  // The open held the worker for a while; the loop's timer kept time all along.
  std::printf("rig_open failed after %.2f s; the loop's timer was late by %.1f ms at worst\n",
              open_s, watch.worst_late_s() * 1e3);
  EXPECT_GT(open_s, 0.5) << "an open this quick proves nothing about the loop";
  EXPECT_LT(watch.worst_late_s(), 0.1);
  ASSERT_EQ(heard.downs(), 1U);
  EXPECT_EQ(heard.links[0].second, why);
}

TEST(HamlibRig, RetriesUntilRigctldListensThenReconnectsAfterItIsKilled) {
  const std::uint16_t port = free_port();
  ASSERT_NE(port, 0);
  boost::asio::io_context io;
  LoopWatch watch(io);
  Heard heard;
  HamlibRig rig(io, HamlibRigConfig{2, "127.0.0.1:" + std::to_string(port), 0}, quick_retries(),
                heard.callbacks());
  // Nothing listens: refused at once, again and again, and said once.
  ASSERT_TRUE(run_for_until(io, 5.0, [&] { return rig.open_attempts() >= 4; }));
  EXPECT_EQ(rig.state(), RigLinkState::Down);
  EXPECT_NE(rig.down_reason().find("127.0.0.1:" + std::to_string(port)), std::string::npos)
      << rig.down_reason();
  EXPECT_EQ(heard.downs(), 1U);

  Rigctld rigctld(port);
  rigctld.start();
  const auto listening = Clock::now();
  ASSERT_TRUE(run_for_until(io, 5.0, [&] { return rig.up(); })) << rig.down_reason();
  std::printf("up %.2f s after rigctld started\n", seconds_since(listening));
  ASSERT_TRUE(rig.set_rx_hz(435123456.0));
  rig.flush();
  ASSERT_TRUE(run_until(io, [&] { return heard.count(RigEventKind::RxRead) == 1; }));
  EXPECT_DOUBLE_EQ(heard.events.back().hz, 435123456.0);

  // Killed: the idle check finds it gone with nothing asked; started again: up again.
  rigctld.stop();
  ASSERT_TRUE(run_for_until(io, 5.0, [&] { return rig.state() == RigLinkState::Down; }));
  EXPECT_EQ(heard.downs(), 2U);
  rigctld.start();
  ASSERT_TRUE(run_for_until(io, 5.0, [&] { return rig.up(); })) << rig.down_reason();
  EXPECT_EQ(heard.links.size(), 4U) << "down, up, down, up: once each";
  EXPECT_LT(watch.worst_late_s(), 0.1);
}

TEST(HamlibRig, ShutdownWaitsForACallInFlightOnlyAsLongAsItWasTold) {
  // A peer that accepts and never answers: NET rigctl's rig_open waits 10 s for each of its tries.
  const int listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  ASSERT_GE(listener, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof(address);
  ASSERT_EQ(::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  ASSERT_EQ(::getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length), 0);
  ASSERT_EQ(::listen(listener, 4), 0);
  boost::asio::io_context io;
  Heard heard;
  HamlibRigOptions options = quick_retries();
  options.close_wait_s = 0.2;
  auto rig = std::make_unique<HamlibRig>(
      io, HamlibRigConfig{2, "127.0.0.1:" + std::to_string(ntohs(address.sin_port)), 0}, options,
      heard.callbacks());
  run_for_until(io, 0.3, [] { return false; });
  EXPECT_EQ(rig->state(), RigLinkState::Connecting) << "rig_open still waits for the peer";
  const auto closing = Clock::now();
  rig.reset();
  const double closed_s = seconds_since(closing);
  std::printf("closed in %.2f s with rig_open in flight\n", closed_s);
  EXPECT_LT(closed_s, 1.0);
  io.run_for(std::chrono::milliseconds(50));
  EXPECT_TRUE(heard.links.empty()) << "nothing is said once the owner is gone";
  ::close(listener);  // the left worker's rig_open ends, it closes the rig and the thread ends
}

// Hamlib 4.5's rig_check_backend registers a loaded backend a second time when the model number
// is in its range but not one of its rigs, and rig_register then exits the process ("Hash
// collision!!! Fatal error!!"). A settings save naming model 1070 after a Yaesu rig was checked
// must be a clear error, not the end of the daemon (config_fuzz found it).
TEST(HamlibRigModel, AModelMissingFromALoadedBackendIsAnErrorNotAnExit) {
  const auto ft817 = hamlib_rig_model(1020);
  ASSERT_TRUE(ft817) << ft817.error().message;
  EXPECT_NE(ft817->name.find("817"), std::string::npos) << ft817->name;
  EXPECT_EQ(ft817->port, HamlibPortKind::Serial);
  for (int i = 0; i < 2; ++i) {
    const auto missing = hamlib_rig_model(1070);
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("no rig model 1070"), std::string::npos);
  }
  EXPECT_FALSE(hamlib_rig_model(0));
  EXPECT_FALSE(hamlib_rig_model(-5));
  EXPECT_TRUE(hamlib_rig_model(1020)) << "the backend is still there";
  EXPECT_NE(hamlib_rig_config_problem(HamlibRigConfig{1, "", 9600}).find("not a serial rig"),
            std::string::npos);
}

}  // namespace
}  // namespace azt::linux_os
