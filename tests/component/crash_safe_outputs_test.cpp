// A crash leaves no PWM driving (docs/reliability.md R16): a child process opens a channel of a
// fake sysfs PWM chip through SysfsPwm, drives it, installs the crash handlers and dies by a
// fatal signal. No destructor runs in a crash; the handler's registered writes must still have
// zeroed the duty and disabled the channel, and the child must still die by that signal.
#include "azt/linux/crash_safe_outputs.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "azt/linux/sysfs_pwm.hpp"

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::string v;
  in >> v;
  return v;
}

class CrashSafeOutputs : public ::testing::TestWithParam<int> {};

TEST_P(CrashSafeOutputs, AFatalSignalZeroesTheDutyAndDisablesTheChannel) {
  const int signal = GetParam();
  const fs::path chip = fs::temp_directory_path() /
                        ("azt_crash_" + std::to_string(::getpid()) + "_" + std::to_string(signal));
  fs::remove_all(chip);
  fs::create_directories(chip / "pwm0");
  std::ofstream(chip / "export") << "";
  for (const char* f : {"period", "duty_cycle", "enable"}) std::ofstream(chip / "pwm0" / f) << "0";

  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    auto pwm = SysfsPwm::open(chip.string(), 0, 1000.0);
    if (!pwm || !pwm.value().set_duty(0.6)) ::_exit(3);
    install_crash_handlers();
    const rlimit no_core{0, 0};
    (void)::setrlimit(RLIMIT_CORE, &no_core);  // a test's crash leaves no core file behind
    ::raise(signal);                           // as a crash would: no destructor, no stop
    ::_exit(4);                                // not reached when the handler re-raises
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child exited with " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), signal) << "the handler must let the signal end the process";
  EXPECT_EQ(read_text(chip / "pwm0" / "duty_cycle"), "0");
  EXPECT_EQ(read_text(chip / "pwm0" / "enable"), "0");
  fs::remove_all(chip);
}

INSTANTIATE_TEST_SUITE_P(Signals, CrashSafeOutputs,
                         ::testing::Values(SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL));

}  // namespace
}  // namespace azt::linux_os
