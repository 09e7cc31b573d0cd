// The station's hard inputs and the T/R sequencer on the daemon's loop (docs/hardware.md):
// [gpio] configuration, the sequencer's real-time order and gaps on GPIO outputs, the E-stop
// latch (across a restart), limit switches, and lines that cannot be had — against a GPIO
// provider in memory (tests/app/fake_gpio.hpp) and the simulated antenna.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "antenna/antenna_backend.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "station/guarded_antenna.hpp"
#include "station/sequencer_runner.hpp"
#include "support/fake_gpio.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using testing::FakeGpio;
using testing::GpioWrite;

DaemonConfig parse(const std::string& text) {
  return daemon_config_from(ConfigFile::parse("[station]\ngrid = \"FN06HE\"\n" + text, "t.toml"));
}

std::string error_of(const std::string& text) {
  try {
    (void)parse(text);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(GpioConfig, LinesNumbersChipsAndPolarities) {
  const DaemonConfig c = parse(
      "[gpio]\nchip = \"gpiochip0\"\nestop = 26\naz_cw_limit = \"gpiochip1:5\"\nptt = 17\n"
      "sequencer = [22, 23, 24, 25]\nsequencer_active_low = true\n");
  ASSERT_TRUE(c.gpio.estop && c.gpio.az_cw_limit && c.gpio.ptt);
  EXPECT_EQ(c.gpio.estop->offset, 26U);
  EXPECT_FALSE(c.gpio.estop->active_low) << "an NC E-stop to ground reads high when pressed";
  EXPECT_EQ(c.gpio.az_cw_limit->chip, "gpiochip1");
  EXPECT_EQ(c.gpio.az_cw_limit->offset, 5U);
  EXPECT_TRUE(c.gpio.ptt->active_low) << "PTT pulls its line to ground";
  ASSERT_EQ(c.gpio.sequencer.size(), 4U);
  EXPECT_TRUE(c.gpio.sequencer[0].active_low);
  EXPECT_EQ(c.gpio.sequencer[3].key, "[gpio] sequencer[3]");
  EXPECT_FALSE(parse("").gpio.any_line());
}

TEST(GpioConfig, MistakesNameTheKey) {
  EXPECT_NE(error_of("[gpio]\nestop = 5\naz_cw_limit = 5\n").find("same line as [gpio] estop"),
            std::string::npos);
  EXPECT_NE(error_of("[gpio]\nsequencer = [1, 2]\n").find("2 lines for 4 [sequencer] outputs"),
            std::string::npos);
  EXPECT_NE(error_of("[gpio]\nptt = 3\n").find("[gpio].ptt needs"), std::string::npos);
  EXPECT_NE(error_of("[gpio]\nestop = -1\n").find("[gpio].estop must be a line number"),
            std::string::npos);
  EXPECT_NE(error_of("[gpio]\nestop = \"chip\"\n").find("[gpio].estop must be"), std::string::npos);
  EXPECT_NE(error_of("[gpio]\nestop = \"gpiochip0:x\"\n").find("[gpio].estop must be"),
            std::string::npos);
  EXPECT_NE(error_of("[gpio]\nrelay = 3\n").find("relay"), std::string::npos);
}

/// Runs the loop until `done` or `limit` of real time has passed.
template <typename Done>
bool run_until(boost::asio::io_context& io, Done done, std::chrono::milliseconds limit) {
  const auto end = Clock::now() + limit;
  while (!done() && Clock::now() < end) {
    io.run_for(std::chrono::milliseconds(1));
    io.restart();
  }
  return done();
}

struct SequencerRig {
  boost::asio::io_context io;
  FakeGpio gpio{io};
  Clock::time_point start = Clock::now();
  std::vector<std::string> log;
  std::unique_ptr<SequencerRunner> runner;

  explicit SequencerRig(const sequencer::SequencerConfig& config) {
    std::vector<std::unique_ptr<linux_os::GpioOutput>> outputs;
    for (std::size_t i = 0; i < config.outputs.size(); ++i) {
      outputs.push_back(gpio.output({"gpiochip0", static_cast<unsigned>(20 + i), false,
                                     "[gpio] sequencer[" + std::to_string(i) + "]"},
                                    false)
                            .value());
    }
    gpio.writes.clear();
    runner = std::make_unique<SequencerRunner>(
        io, config, std::move(outputs),
        [this] { return std::chrono::duration<double>(Clock::now() - start).count(); },
        [this](const std::string& line) { log.push_back(line); });
  }
  [[nodiscard]] bool all(bool on) const {
    for (std::size_t i = 0; i < runner->core().outputs().size(); ++i) {
      if (gpio.outputs.at("[gpio] sequencer[" + std::to_string(i) + "]") != on) return false;
    }
    return true;
  }
};

/// Every write's line, and the real gaps between consecutive writes (ms).
void expect_order_and_gaps(const std::vector<GpioWrite>& writes,
                           const std::vector<std::string>& order, double delay_ms) {
  ASSERT_EQ(writes.size(), order.size());
  for (std::size_t i = 0; i < writes.size(); ++i) {
    EXPECT_EQ(writes[i].key, order[i]) << "write " << i;
    if (i == 0) continue;
    const double gap_ms =
        std::chrono::duration<double, std::milli>(writes[i].at - writes[i - 1].at).count();
    // The writes are stamped after the timer's clock read: 0.2 ms of slack for that read.
    EXPECT_GE(gap_ms, delay_ms - 0.2) << "between " << order[i - 1] << " and " << order[i];
  }
}

TEST(SequencerRunner, KeysInOrderAndReleasesInReverseWithRealGaps) {
  const auto config = sequencer::SequencerConfig::seed_default();  // 4 outputs, 20 ms apart
  SequencerRig rig(config);
  rig.runner->set_ptt(true);
  ASSERT_TRUE(run_until(
      rig.io, [&] { return rig.all(true); }, std::chrono::seconds(2)));
  EXPECT_TRUE(rig.runner->core().transmitting());
  EXPECT_TRUE(rig.runner->motion_hold());
  expect_order_and_gaps(
      rig.gpio.writes,
      {"[gpio] sequencer[0]", "[gpio] sequencer[1]", "[gpio] sequencer[2]", "[gpio] sequencer[3]"},
      20.0);
  rig.gpio.writes.clear();
  rig.runner->set_ptt(false);
  ASSERT_TRUE(run_until(
      rig.io, [&] { return rig.all(false); }, std::chrono::seconds(2)));
  expect_order_and_gaps(
      rig.gpio.writes,
      {"[gpio] sequencer[3]", "[gpio] sequencer[2]", "[gpio] sequencer[1]", "[gpio] sequencer[0]"},
      20.0);
  EXPECT_FALSE(rig.runner->motion_hold());
  const auto state = rig.runner->state();
  EXPECT_EQ(state["outputs"][0]["name"], "preamp");
  EXPECT_FALSE(state["outputs"][0]["on"].get<bool>());
}

TEST(SequencerRunner, AnInhibitMidKeyingReleasesWhatWasKeyedInReverse) {
  SequencerRig rig(sequencer::SequencerConfig::seed_default());
  rig.runner->set_ptt(true);
  ASSERT_TRUE(run_until(
      rig.io, [&] { return rig.gpio.outputs["[gpio] sequencer[1]"]; }, std::chrono::seconds(2)));
  rig.runner->set_inhibit(true);  // the E-stop
  ASSERT_TRUE(run_until(
      rig.io, [&] { return rig.all(false); }, std::chrono::seconds(2)));
  // Keyed 0 and 1, then released 1 before 0; the amplifier and radio were never keyed.
  std::vector<std::string> keys;
  for (const auto& w : rig.gpio.writes) keys.push_back(w.key + (w.active ? " on" : " off"));
  EXPECT_EQ(keys, (std::vector<std::string>{"[gpio] sequencer[0] on", "[gpio] sequencer[1] on",
                                            "[gpio] sequencer[1] off", "[gpio] sequencer[0] off"}));
  // Still inhibited: PTT held does not key again.
  rig.io.run_for(std::chrono::milliseconds(100));
  EXPECT_TRUE(rig.all(false));
  EXPECT_TRUE(rig.runner->state()["inhibited"].get<bool>());
}

TEST(SequencerRunner, AnOutputThatCannotBeWrittenLatchesAFaultAndReleases) {
  SequencerRig rig(sequencer::SequencerConfig::seed_default());
  rig.runner->set_ptt(true);
  ASSERT_TRUE(run_until(
      rig.io, [&] { return rig.gpio.outputs["[gpio] sequencer[1]"]; }, std::chrono::seconds(2)));
  rig.gpio.fail_writes(true);  // the GPIO chip is gone
  ASSERT_TRUE(run_until(
      rig.io, [&] { return !rig.runner->fault().empty(); }, std::chrono::seconds(2)));
  EXPECT_NE(rig.runner->fault().find("write failed"), std::string::npos) << rig.runner->fault();
  rig.gpio.fail_writes(false);
  // The chain runs down in the core even though writes failed; the amplifier never keys.
  ASSERT_TRUE(run_until(
      rig.io, [&] { return !rig.runner->core().outputs()[0]; }, std::chrono::seconds(2)));
  EXPECT_FALSE(rig.gpio.outputs["[gpio] sequencer[2]"]);
  rig.runner->clear_fault();
  ASSERT_TRUE(run_until(
      rig.io, [&] { return rig.all(true); }, std::chrono::seconds(2)))
      << "PTT still held: keying resumes once the operator clears the fault";
}

class GuardTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("azt_guard_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    config_ = parse(
        "[target]\nname = \"stop\"\n[sim.az]\nstart_deg = 180.0\n[sim.el]\nstart_deg = 10.0\n"
        "[gpio]\nestop = 26\naz_ccw_limit = 5\naz_cw_limit = 6\nel_down_limit = 13\n"
        "el_up_limit = 19\nptt = 17\nsequencer = [22, 23, 24, 25]\n");
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// The control loop's clock: virtual, advanced by the ticks below.
  [[nodiscard]] double now() const { return t_; }
  /// The sequencer's clock: real, since its steps run on the loop's timers.
  [[nodiscard]] double real_now() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }
  std::unique_ptr<GuardedAntenna> guard(FakeGpio& gpio, SequencerRunner* runner) {
    return std::make_unique<GuardedAntenna>(
        make_sim_backend(config_), config_.gpio,
        GuardParts{&gpio, runner, (dir_ / "estop.latched").string(), [this] { return now(); },
                   [this] { ++estops_; }, [this](const std::string& l) { log_.push_back(l); }});
  }
  /// Ticks at 20 Hz for `seconds` of virtual time with `demand`, delivering pending edges first.
  void run(boost::asio::io_context& io, AntennaBackend& a, const control::Demand& demand,
           double seconds) {
    for (const double end = t_ + seconds; t_ < end;) {
      t_ += 0.05;
      io.poll();
      io.restart();
      a.tick(t_, demand, control::AzEl{});
    }
  }

  fs::path dir_;
  DaemonConfig config_;
  Clock::time_point start_ = Clock::now();
  double t_ = 0.0;
  int estops_ = 0;
  std::vector<std::string> log_;
};

TEST_F(GuardTest, EStopStopsReleasesThePttChainAndStaysLatchedAcrossARestart) {
  boost::asio::io_context io;
  FakeGpio gpio(io);
  std::vector<std::unique_ptr<linux_os::GpioOutput>> outputs;
  for (const auto& spec : config_.gpio.sequencer)
    outputs.push_back(gpio.output(spec, false).value());
  SequencerRunner runner(
      io, config_.sequencer, std::move(outputs), [this] { return real_now(); },
      [](const std::string&) {});
  auto antenna = guard(gpio, &runner);
  control::Demand go;
  go.position = control::AzEl{200.0, 10.0};
  run(io, *antenna, go, 1.0);
  ASSERT_TRUE(antenna->faults().empty());
  runner.set_ptt(true);
  ASSERT_TRUE(run_until(
      io, [&] { return runner.core().transmitting(); }, std::chrono::seconds(2)));

  gpio.set_input("[gpio] estop", true);
  ASSERT_TRUE(run_until(
      io, [&] { return antenna->estop_latched(); }, std::chrono::seconds(1)));
  EXPECT_EQ(estops_, 1) << "the daemon is told (mode to STOP)";
  ASSERT_FALSE(antenna->faults().empty());
  EXPECT_NE(antenna->faults().front().find("E-stop"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "estop.latched"));
  ASSERT_TRUE(run_until(
      io, [&] { return gpio.outputs["[gpio] sequencer[0]"] == false; }, std::chrono::seconds(2)));
  for (const auto& spec : config_.gpio.sequencer) EXPECT_FALSE(gpio.outputs[spec.key]) << spec.key;
  EXPECT_FALSE(antenna->position(now()).has_value()) << "no position is served while E-stopped";
  run(io, *antenna, go, 0.5);  // the plant's coast
  const auto before = antenna->encoder_reading();
  ASSERT_TRUE(before.has_value());
  run(io, *antenna, go, 1.0);
  EXPECT_NEAR(antenna->encoder_reading()->az_deg, before->az_deg, 0.01) << "moved while E-stopped";

  // The button is still pressed: clearing does nothing.
  antenna->clear_faults();
  EXPECT_TRUE(antenna->estop_latched());

  // Released, then the daemon restarts: the latch is remembered.
  gpio.set_input("[gpio] estop", false);
  io.poll();
  io.restart();
  antenna.reset();
  auto again = guard(gpio, &runner);
  EXPECT_TRUE(again->estop_latched());
  ASSERT_FALSE(again->faults().empty());
  EXPECT_NE(again->faults().front().find("before this start"), std::string::npos);
  again->clear_faults();
  EXPECT_FALSE(again->estop_latched());
  EXPECT_FALSE(fs::exists(dir_ / "estop.latched"));
  EXPECT_TRUE(again->faults().empty());
  ASSERT_TRUE(run_until(
      io, [&] { return runner.core().transmitting(); }, std::chrono::seconds(2)))
      << "PTT still held after the operator cleared the E-stop: the chain keys again";
}

TEST_F(GuardTest, AnEStopHeldAtStartLatchesAtOnce) {
  boost::asio::io_context io;
  FakeGpio gpio(io);
  gpio.preset("[gpio] estop", true);
  auto antenna = guard(gpio, nullptr);
  EXPECT_TRUE(antenna->estop_latched());
  EXPECT_TRUE(antenna->state()["estop"]["input"].get<bool>());
}

TEST_F(GuardTest, ALimitSwitchStopsTheDriveTowardsItAndReportsIt) {
  boost::asio::io_context io;
  FakeGpio gpio(io);
  auto antenna = guard(gpio, nullptr);
  control::Demand cw;
  cw.position = control::AzEl{260.0, 10.0};
  run(io, *antenna, cw, 2.0);
  const double moving_at = antenna->position(now())->az_deg;
  ASSERT_GT(moving_at, 180.5) << "the simulated azimuth never started";
  gpio.set_input("[gpio] az_cw_limit", true);
  io.poll();
  io.restart();
  EXPECT_TRUE(antenna->limits().az_cw);
  EXPECT_TRUE(antenna->state()["limits"]["az_cw"].get<bool>());
  // Coasting (the plant's time constant) then standing: less than a degree after the edge.
  run(io, *antenna, cw, 2.0);
  const double held_at = antenna->position(now())->az_deg;
  EXPECT_LT(held_at - moving_at, 1.0);
  EXPECT_TRUE(antenna->faults().empty()) << antenna->faults().front();
  control::Demand ccw;
  ccw.position = control::AzEl{170.0, 10.0};
  run(io, *antenna, ccw, 2.0);
  EXPECT_LT(antenna->position(now())->az_deg, held_at - 0.5) << "could not leave the switch";
}

// The polarisation axis's switches ([gpio] pol_ccw_limit / pol_cw_limit): the feed stops on the
// edge, the state shows it, and the feed can still turn away.
TEST_F(GuardTest, APolLimitSwitchStopsTheFeedTowardsIt) {
  config_ = parse(
      "[target]\nname = \"stop\"\n[mount.pol]\nmax_rate_deg_s = 3.0\n[gpio]\n"
      "pol_ccw_limit = 20\npol_cw_limit = 21\n");
  boost::asio::io_context io;
  FakeGpio gpio(io);
  auto antenna = guard(gpio, nullptr);
  antenna->set_pol_demand(control::PolDemand{80.0, 0.0});
  run(io, *antenna, control::Demand{}, 3.0);
  const double moving_at = antenna->pol_status()->mount_deg;
  ASSERT_GT(moving_at, 3.0) << "the simulated feed never started";
  gpio.set_input("[gpio] pol_cw_limit", true);
  io.poll();
  io.restart();
  EXPECT_TRUE(antenna->state()["limits"]["pol_cw"].get<bool>());
  EXPECT_FALSE(antenna->state()["limits"]["pol_ccw"].get<bool>());
  run(io, *antenna, control::Demand{}, 3.0);
  const double held_at = antenna->pol_status()->mount_deg;
  EXPECT_LT(held_at - moving_at, 1.5) << "ran on past the switch";
  EXPECT_TRUE(antenna->faults().empty()) << antenna->faults().front();
  antenna->set_pol_demand(control::PolDemand{-30.0, 0.0});
  run(io, *antenna, control::Demand{}, 3.0);
  EXPECT_LT(antenna->pol_status()->mount_deg, held_at - 1.0) << "could not leave the switch";
  EXPECT_NE(error_of("[gpio]\npol_cw_limit = 21\n").find("[mount.pol]"), std::string::npos);
}

TEST_F(GuardTest, AnotherProgramsHoldIsAppliedAtTheNextTickAndSaysSince) {
  boost::asio::io_context io;
  FakeGpio gpio(io);
  auto antenna = guard(gpio, nullptr);
  bool transmitting = false;
  antenna->set_other_hold([&transmitting] { return transmitting; });
  control::Demand cw;
  cw.position = control::AzEl{260.0, 10.0};
  run(io, *antenna, cw, 1.0);
  EXPECT_EQ(antenna->held_since_s(), std::nullopt);
  transmitting = true;
  const double asked_at = now();
  run(io, *antenna, cw, 0.05);
  ASSERT_TRUE(antenna->held_since_s());
  EXPECT_DOUBLE_EQ(*antenna->held_since_s(), asked_at + 0.05) << "the next tick holds";
  run(io, *antenna, cw, 1.0);
  EXPECT_DOUBLE_EQ(*antenna->held_since_s(), asked_at + 0.05) << "the start of the hold is kept";
  transmitting = false;
  run(io, *antenna, cw, 0.05);
  EXPECT_EQ(antenna->held_since_s(), std::nullopt);
}

TEST_F(GuardTest, ALineThatCannotBeHadIsAnErrorNamingItsKey) {
  boost::asio::io_context io;
  FakeGpio gpio(io);
  gpio.make_busy(13);
  try {
    (void)guard(gpio, nullptr);
    FAIL() << "started with a busy line";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[gpio] el_down_limit"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace azt::app
