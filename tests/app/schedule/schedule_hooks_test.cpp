// The schedule's hooks (docs/satellites.md "Hooks") with real scripts in a temporary folder: the
// environment is the pass's and nothing else of ours, the ending and the first lines come back on
// the loop, a hung hook is killed at its timeout, a flood is cut, what cannot run says why, a
// fifth hook at once is refused, the owner's end kills what runs, and the loop keeps its time
// while a hook sleeps. The loop runs in short slices until what a test waits for has happened.
#include "schedule/schedule_hooks.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "azt/util/valid_utf8.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

class ScriptDir {
 public:
  ScriptDir() {
    std::string pattern = (fs::temp_directory_path() / "azt_hooks_XXXXXX").string();
    if (::mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~ScriptDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScriptDir(const ScriptDir&) = delete;
  ScriptDir& operator=(const ScriptDir&) = delete;

  /// An executable `#!/bin/sh` script running `body`; its absolute path.
  [[nodiscard]] std::string script(const std::string& name, const std::string& body,
                                   mode_t mode = 0700) const {
    std::string p = at(name);
    std::ofstream(p) << "#!/bin/sh\n" << body << "\n";
    ::chmod(p.c_str(), mode);
    return p;
  }
  [[nodiscard]] std::string at(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

/// Runs the loop until `done` or 10 s pass; false on timeout.
template <typename Done>
bool run_until(boost::asio::io_context& io, Done done) {
  const auto end = Clock::now() + std::chrono::seconds(10);
  while (!done() && Clock::now() < end) {
    io.run_for(std::chrono::milliseconds(10));
    io.restart();
  }
  return done();
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t count_lines(const std::string& path) {
  const std::string text = read_file(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

bool process_exists(pid_t pid) { return ::kill(pid, 0) == 0 || errno != ESRCH; }

const HookPass kIss{.sat = "ISS (ZARYA)",
                    .norad = "25544",
                    .aos_unix_s = 1714566896.0,  // `date -u -d @1714566896`: 2024-05-01T12:34:56Z
                    .los_unix_s = 1714567496.25,
                    .max_el_deg = 47.31};

HooksConfig with_aos(std::vector<std::string> argv, double timeout_s = 10.0) {
  HooksConfig c;
  c.aos = std::move(argv);
  c.timeout_s = timeout_s;
  return c;
}

/// The hooks of `config`, whose reports land in `reports`.
struct Rig {
  boost::asio::io_context io;
  std::vector<std::string> reports;
  std::unique_ptr<ScheduleHooks> hooks;

  explicit Rig(HooksConfig config)
      : hooks(std::make_unique<ScheduleHooks>(
            io, std::move(config), [this](const std::string& line) { reports.push_back(line); })) {}

  /// Fires `event` and waits for its report.
  std::string fire_and_wait(HookEvent event, const HookPass& pass = kIss) {
    const std::size_t before = reports.size();
    hooks->fire(event, pass);
    EXPECT_TRUE(run_until(io, [&] { return reports.size() > before; }));
    return reports.size() > before ? reports.back() : std::string("(no report)");
  }
};

std::set<std::string> lines_of(const std::string& text) {
  std::set<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("PWD=", 0) != 0) out.insert(line);  // sh's own, not ours
  }
  return out;
}

TEST(ScheduleHooks, TheEnvironmentIsThePassAndNothingElseOfOurs) {
  ASSERT_EQ(::setenv("HOME", "/home/station", 1), 0);
  ASSERT_EQ(::setenv("LANG", "en_GB.UTF-8", 1), 0);
  ASSERT_EQ(::setenv("AZT_HOOK_TEST_SECRET", "not for hooks", 1), 0);
  const ScriptDir dir;
  Rig rig(with_aos({dir.script("env.sh", "/usr/bin/env > \"$1\""), dir.at("env.txt")}));
  EXPECT_NE(rig.fire_and_wait(HookEvent::Aos).find("exited 0"), std::string::npos);
  EXPECT_EQ(
      lines_of(read_file(dir.at("env.txt"))),
      (std::set<std::string>{"AZT_EVENT=aos", "AZT_SAT=ISS (ZARYA)", "AZT_NORAD=25544",
                             "AZT_AOS=2024-05-01T12:34:56.000Z", "AZT_LOS=2024-05-01T12:44:56.250Z",
                             "AZT_MAX_EL=47.3", "PATH=/usr/local/bin:/usr/bin:/bin",
                             "HOME=/home/station", "LANG=en_GB.UTF-8"}));
  ::unsetenv("AZT_HOOK_TEST_SECRET");
}

TEST(ScheduleHooks, AParkWithoutAPassHasEmptyPassVariables) {
  const ScriptDir dir;
  HooksConfig c;
  c.park = {dir.script("park.sh", "echo \"[$AZT_EVENT|$AZT_SAT|$AZT_AOS|$AZT_MAX_EL]\"")};
  Rig rig(c);
  const std::string report = rig.fire_and_wait(HookEvent::Park, HookPass{});
  EXPECT_EQ(report.rfind("hook park: " + c.park[0] + ": exited 0 in ", 0), 0U) << report;
  EXPECT_TRUE(report.ends_with(" s: [park|||]")) << report;
}

TEST(ScheduleHooks, EachEventRunsItsOwnProgram) {
  const ScriptDir dir;
  HooksConfig c;
  c.aos = {dir.script("a.sh", "echo aos-program $AZT_EVENT")};
  c.los = {dir.script("l.sh", "echo los-program $AZT_EVENT")};
  c.pre_position = {dir.script("p.sh", "echo pre-program $AZT_EVENT")};
  Rig rig(c);
  EXPECT_NE(rig.fire_and_wait(HookEvent::Los).find(": los-program los"), std::string::npos);
  EXPECT_NE(rig.fire_and_wait(HookEvent::PrePosition).find(": pre-program pre_position"),
            std::string::npos);
  EXPECT_NE(rig.fire_and_wait(HookEvent::Aos).find(": aos-program aos"), std::string::npos);
  rig.hooks->fire(HookEvent::Park, kIss);  // none configured: nothing runs, nothing is said
  EXPECT_EQ(rig.hooks->running(), 0U);
  rig.io.poll();
  EXPECT_EQ(rig.reports.size(), 3U);
}

TEST(ScheduleHooks, TheExitStatusAndFirstLinesAreReported) {
  const ScriptDir dir;
  const auto program = dir.script("fail.sh", "echo first; echo second >&2; exit 3");
  Rig rig(with_aos({program}));
  const std::string report = rig.fire_and_wait(HookEvent::Aos);
  EXPECT_EQ(report.rfind("hook aos ISS (ZARYA) (25544): " + program + ": exited 3 in ", 0), 0U)
      << report;
  EXPECT_NE(report.find(" s: first | second"), std::string::npos) << report;
  EXPECT_EQ(rig.hooks->running(), 0U);
}

TEST(ScheduleHooks, AHungHookIsKilledAtItsTimeout) {
  const ScriptDir dir;
  const auto started = Clock::now();
  Rig rig(with_aos({dir.script("hang.sh", "echo $$ > \"$1\"; exec /bin/sleep 60"), dir.at("pid")},
                   0.3));
  const std::string report = rig.fire_and_wait(HookEvent::Aos);
  const double took_s = std::chrono::duration<double>(Clock::now() - started).count();
  EXPECT_NE(report.find("killed after its 0.3 s timeout"), std::string::npos) << report;
  EXPECT_LT(took_s, 3.0) << "not the hook's 60 s";
  const pid_t pid = std::stoi(read_file(dir.at("pid")));
  EXPECT_FALSE(process_exists(pid)) << "the hook's sleep " << pid << " is gone";
}

TEST(ScheduleHooks, AFloodIsCutAndNeverBlocks) {
  const ScriptDir dir;
  Rig rig(with_aos({dir.script("flood.sh", "/usr/bin/seq 1 200000")}));
  const std::string report = rig.fire_and_wait(HookEvent::Aos);
  EXPECT_NE(report.find("exited 0"), std::string::npos) << report;
  EXPECT_NE(report.find(": 1 | 2 | 3 | 4 | 5 | 6 | 7 | 8 | 9 | 10 (+"), std::string::npos)
      << report;
  EXPECT_NE(report.find(" bytes not kept)"), std::string::npos) << report;
}

TEST(ScheduleHooks, AnEndlessFloodEndsAtTheTimeout) {
  Rig rig(with_aos({"/usr/bin/yes", "flood"}, 0.3));
  const std::string report = rig.fire_and_wait(HookEvent::Aos);
  EXPECT_NE(report.find("killed after its 0.3 s timeout: flood | flood"), std::string::npos)
      << report;
}

TEST(ScheduleHooks, HostileOutputIsMadeSafeText) {
  const ScriptDir dir;
  Rig rig(with_aos({dir.script("garbage.sh", "printf 'a\\033[2Jb\\377\\300c\\rd\\n'")}));
  const std::string report = rig.fire_and_wait(HookEvent::Aos);
  EXPECT_TRUE(is_valid_utf8(report));
  EXPECT_EQ(report.find('\033'), std::string::npos);
  EXPECT_EQ(report.find('\r'), std::string::npos);
  EXPECT_NE(report.find(": a?[2Jb\xEF\xBF\xBD\xEF\xBF\xBD"
                        "c?d"),
            std::string::npos)
      << report;
}

TEST(ScheduleHooks, WhatCannotRunSaysWhy) {
  const ScriptDir dir;
  Rig missing(with_aos({dir.at("missing.sh")}));
  EXPECT_NE(missing.fire_and_wait(HookEvent::Aos)
                .find("did not run: " + dir.at("missing.sh") + ": No such file or directory"),
            std::string::npos);
  Rig plain(with_aos({dir.script("plain.sh", "echo hi", 0600)}));
  EXPECT_NE(plain.fire_and_wait(HookEvent::Aos)
                .find("did not run: " + dir.at("plain.sh") + ": Permission denied"),
            std::string::npos);
}

TEST(ScheduleHooks, AFifthHookAtOnceIsRefusedAndTheEndKillsTheRest) {
  const ScriptDir dir;
  const auto program = dir.script("slow.sh", "echo $$ >> \"$1\"; exec /bin/sleep 60");
  Rig rig(with_aos({program, dir.at("pids")}, 30.0));
  for (int i = 0; i < 4; ++i) rig.hooks->fire(HookEvent::Aos, kIss);
  EXPECT_EQ(rig.hooks->running(), 4U);
  rig.hooks->fire(HookEvent::Aos, kIss);
  ASSERT_EQ(rig.reports.size(), 1U);
  EXPECT_EQ(rig.reports[0],
            "hook aos ISS (ZARYA) (25544): " + program + ": not run: 4 hooks are still running");
  EXPECT_EQ(rig.hooks->running(), 4U);
  ASSERT_TRUE(run_until(rig.io, [&] { return count_lines(dir.at("pids")) == 4; }));
  const auto asked = Clock::now();
  rig.hooks.reset();
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - asked).count(), 1.0)
      << "the end kills at once, it does not wait for the 30 s timeout";
  std::istringstream pids(read_file(dir.at("pids")));
  for (pid_t pid = 0; pids >> pid;) EXPECT_FALSE(process_exists(pid)) << pid;
  rig.io.poll();  // the threads' posted endings find no owner, and do nothing
  EXPECT_EQ(rig.reports.size(), 1U);
}

TEST(ScheduleHooks, TheLoopKeepsItsTimeWhileAHookSleeps) {
  Rig rig(with_aos({"/bin/sleep", "1"}));
  constexpr auto kPeriod = std::chrono::milliseconds(20);
  boost::asio::steady_timer timer(rig.io);
  auto due = Clock::now() + kPeriod;
  double worst_late_s = 0.0;
  int ticks = 0;
  std::function<void()> arm = [&] {
    timer.expires_at(due);
    timer.async_wait([&](const boost::system::error_code& ec) {
      if (ec) return;
      worst_late_s =
          std::max(worst_late_s, std::chrono::duration<double>(Clock::now() - due).count());
      ++ticks;
      due += kPeriod;
      arm();
    });
  };
  arm();
  const auto started = Clock::now();
  const std::string report = rig.fire_and_wait(HookEvent::Aos);
  const double took_s = std::chrono::duration<double>(Clock::now() - started).count();
  timer.cancel();
  EXPECT_NE(report.find("exited 0"), std::string::npos) << report;
  EXPECT_GE(took_s, 1.0) << "the hook really slept";
  EXPECT_GE(ticks, 40) << "the timer went on firing during the hook's second";
  // On a shared 2-core machine a tick may be a little late; a blocked loop would be a second.
  EXPECT_LT(worst_late_s, 0.25);
}

}  // namespace
}  // namespace azt::app
