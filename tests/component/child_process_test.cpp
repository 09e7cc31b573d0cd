// Running an operator's program (a schedule hook, docs/satellites.md "Hooks") with real programs:
// scripts written to a temporary folder. The environment is exactly the one given, nothing of
// ours leaks in (variables, descriptors, an ignored signal), no shell is ever involved, output is
// merged and cut at its limits while the rest is read away, the deadline takes the whole process
// group down, and a stop from another thread ends it at once.
#include "azt/linux/child_process.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

class ScriptDir {
 public:
  ScriptDir() {
    std::string pattern = (fs::temp_directory_path() / "azt_child_XXXXXX").string();
    if (::mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~ScriptDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScriptDir(const ScriptDir&) = delete;
  ScriptDir& operator=(const ScriptDir&) = delete;

  /// A file `name` holding `text`, with mode `mode`; its absolute path.
  [[nodiscard]] std::string file(const std::string& name, const std::string& text,
                                 mode_t mode = 0700) const {
    std::string p = path_ + "/" + name;
    std::ofstream(p) << text;
    ::chmod(p.c_str(), mode);
    return p;
  }
  /// An executable `#!/bin/sh` script running `body`.
  [[nodiscard]] std::string script(const std::string& name, const std::string& body) const {
    return file(name, "#!/bin/sh\n" + body + "\n");
  }
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
};

ChildSpec spec_of(const std::string& program, double timeout_s = 10.0) {
  ChildSpec s;
  s.argv = {program};
  s.env = {"PATH=/usr/bin:/bin"};
  s.timeout_s = timeout_s;
  return s;
}

/// No such process, or a dead one waiting for its reaper (this machine's pid 1 may not reap
/// orphans): either way it runs no more.
bool gone(pid_t pid) {
  if (::kill(pid, 0) != 0) return errno == ESRCH;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_text, comm, state;
  stat >> pid_text >> comm >> state;
  return state == "Z" || state == "X";
}

bool wait_for_file(const std::string& path) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!fs::exists(path) && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return fs::exists(path);
}

TEST(RunChild, TheEnvironmentIsExactlyTheOneGiven) {
  ASSERT_EQ(::setenv("AZT_CHILD_TEST_LEAK", "ours", 1), 0);
  const ScriptDir dir;
  auto spec = spec_of(
      dir.script("env.sh", "printf '%s|%s|%s\\n' \"$A\" \"$B\" \"${AZT_CHILD_TEST_LEAK-absent}\""));
  spec.env = {"A=1", "B=two words; $(touch x)"};
  const auto r = run_child(spec);
  EXPECT_EQ(r.spawn_error, "");
  EXPECT_EQ(r.first_lines, "1|two words; $(touch x)|absent\n");
  EXPECT_EQ(r.exit_code, 0);
  ::unsetenv("AZT_CHILD_TEST_LEAK");
}

TEST(RunChild, ArgumentsArriveAsGivenWithoutAShell) {
  const ScriptDir dir;
  auto spec = spec_of(dir.script("args.sh", "for a in \"$@\"; do echo \"[$a]\"; done"));
  spec.argv.insert(spec.argv.end(), {"a b", "*", "$HOME", ";echo no"});
  EXPECT_EQ(run_child(spec).first_lines, "[a b]\n[*]\n[$HOME]\n[;echo no]\n");
}

TEST(RunChild, ExitStatusAndSignalComeBack) {
  const ScriptDir dir;
  const auto three = run_child(spec_of(dir.script("three.sh", "exit 3")));
  EXPECT_EQ(three.exit_code, 3);
  EXPECT_EQ(three.signal, 0);
  EXPECT_FALSE(three.timed_out);
  const auto killed = run_child(spec_of(dir.script("self.sh", "kill -9 $$")));
  EXPECT_EQ(killed.exit_code, -1);
  EXPECT_EQ(killed.signal, SIGKILL);
}

TEST(RunChild, OutputAndErrorsAreMergedAndNothingArrivesOnItsInput) {
  const ScriptDir dir;
  const auto r = run_child(spec_of(dir.script("both.sh", "echo out; echo err >&2; cat; echo end")));
  EXPECT_EQ(r.first_lines, "out\nerr\nend\n");
  EXPECT_EQ(r.dropped_bytes, 0U);
}

TEST(RunChild, NoDescriptorOfOursReachesIt) {
  const int ours = ::open("/dev/null", O_RDONLY);  // not close-on-exec, as Asio's sockets are not
  ASSERT_GE(ours, 3);
  auto spec = spec_of("/bin/ls");
  spec.argv.push_back("/proc/self/fd");
  const auto r = run_child(spec);
  ::close(ours);
  EXPECT_EQ(r.first_lines, "0\n1\n2\n3\n") << "ls's own listing is descriptor 3";
}

TEST(RunChild, AnIgnoredSignalOfOursIsNotInherited) {
  // The daemon may ignore SIGTERM or SIGPIPE; a hook must still die of the timeout's SIGTERM.
  const auto before = std::signal(SIGTERM, SIG_IGN);
  auto spec = spec_of("/bin/sleep", 0.2);
  spec.argv.push_back("60");
  const auto slept = run_child(spec);
  std::signal(SIGTERM, before);
  EXPECT_TRUE(slept.timed_out);
  EXPECT_EQ(slept.signal, SIGTERM);
  EXPECT_LT(slept.duration_s, 1.5) << "SIGTERM ended it, not the SIGKILL 2 s later";
}

TEST(RunChild, TheDeadlineTakesDownTheWholeProcessGroup) {
  const ScriptDir dir;
  // The script's own child sleeps; only a kill of the group reaches it.
  const auto r =
      run_child(spec_of(dir.script("hang.sh", "/bin/sleep 60 & echo $!; echo started; wait"), 0.3));
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.signal, SIGTERM);
  EXPECT_LT(r.duration_s, 3.0) << "the timeout held, not the program's 60 s";
  ASSERT_NE(r.first_lines.find("started"), std::string::npos) << r.first_lines;
  const pid_t sleeper = std::stoi(r.first_lines);
  EXPECT_TRUE(gone(sleeper)) << "the script's sleep " << sleeper << " was killed too";
  EXPECT_TRUE(gone(r.pid));
}

TEST(RunChild, OneThatIgnoresSigtermGetsSigkill) {
  const ScriptDir dir;
  auto spec = spec_of(dir.script("stubborn.sh", "trap '' TERM; /bin/sleep 60"), 0.2);
  spec.kill_after_s = 0.3;
  const auto r = run_child(spec);
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.signal, SIGKILL);
  EXPECT_GE(r.duration_s, 0.45);
  EXPECT_LT(r.duration_s, 3.0);
}

TEST(RunChild, AFloodIsCutAtItsBytesAndReadAway) {
  const ScriptDir dir;
  // 1 MB on a 64 KB pipe: unless the rest is read, the program blocks and hits the deadline.
  const auto r = run_child(spec_of(dir.script("flood.sh", "/usr/bin/head -c 1000000 /dev/zero")));
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.first_lines.size(), 2048U);
  EXPECT_EQ(r.dropped_bytes, 1000000U - 2048U);
}

TEST(RunChild, ManyLinesAreCutAtTheTenth) {
  const ScriptDir dir;
  const auto r = run_child(spec_of(dir.script("lines.sh", "/usr/bin/seq 1 100000")));
  EXPECT_EQ(r.first_lines, "1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n");
  std::size_t all_bytes = 0;
  for (int i = 1; i <= 100000; ++i) all_bytes += std::to_string(i).size() + 1;
  EXPECT_EQ(r.dropped_bytes, all_bytes - r.first_lines.size());
}

TEST(RunChild, AnEndlessFloodEndsAtTheDeadline) {
  const auto r = run_child(spec_of("/usr/bin/yes", 0.3));
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.first_lines, "y\ny\ny\ny\ny\ny\ny\ny\ny\ny\n");
  EXPECT_GT(r.dropped_bytes, 10000U);
  EXPECT_LT(r.duration_s, 3.0);
}

TEST(RunChild, WhatCannotRunSaysWhy) {
  const ScriptDir dir;
  const auto missing = run_child(spec_of(dir.path() + "/missing.sh"));
  EXPECT_NE(missing.spawn_error.find("No such file"), std::string::npos) << missing.spawn_error;
  EXPECT_EQ(missing.pid, 0);
  const auto not_exec = run_child(spec_of(dir.file("plain.sh", "#!/bin/sh\necho hi\n", 0600)));
  EXPECT_NE(not_exec.spawn_error.find("Permission denied"), std::string::npos)
      << not_exec.spawn_error;
  // No "#!" line: a shell would run it anyway; posix_spawn refuses it.
  const auto no_shebang = run_child(spec_of(dir.file("bare.sh", "echo hi\n")));
  EXPECT_NE(no_shebang.spawn_error.find("Exec format error"), std::string::npos)
      << no_shebang.spawn_error;
  EXPECT_NE(run_child({}).spawn_error, "");
}

TEST(RunChild, AStopFromAnotherThreadEndsItAtOnce) {
  const ScriptDir dir;
  const std::string marker = dir.path() + "/running";
  const auto spec = spec_of(dir.script("long.sh", ": > " + marker + "; exec /bin/sleep 60"), 60);
  const ChildStop stop;
  ChildResult r;
  std::thread runner([&] { r = run_child(spec, &stop); });
  const bool started = wait_for_file(marker);
  const auto asked = std::chrono::steady_clock::now();
  stop.stop();
  runner.join();
  const double took_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
  ASSERT_TRUE(started);
  EXPECT_TRUE(r.stopped);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.signal, SIGKILL);
  EXPECT_LT(took_s, 1.0);
  EXPECT_TRUE(gone(r.pid));
}

}  // namespace
}  // namespace azt::linux_os
