// Running chronyc off the loop (docs/time.md): the program's output and exit status come back,
// its output is bounded, a hung program is killed at the deadline, a missing one is an error;
// and the kernel's clock state can be read by anyone.
#include "azt/linux/command_output.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "azt/linux/kernel_clock.hpp"

namespace azt::linux_os {
namespace {

TEST(RunCommand, OutputErrorAndStatusComeBack) {
  const auto r = run_command({"sh", "-c", "echo out; echo err >&2; exit 3"});
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r.value().out, "out\n");
  EXPECT_EQ(r.value().err, "err\n");
  EXPECT_EQ(r.value().exit_code, 3);
}

TEST(RunCommand, NothingArrivesOnItsInput) {
  const auto r = run_command({"sh", "-c", "cat; echo done"});
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value().out, "done\n");
}

TEST(RunCommand, OutputIsBoundedAndTheRestDrained) {
  // 1 MB written: the program is not left blocked on a full pipe, and 1000 bytes are kept.
  const auto r = run_command({"sh", "-c", "head -c 1000000 /dev/zero; exit 0"}, {5.0, 1000});
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r.value().out.size(), 1000U);
  EXPECT_EQ(r.value().exit_code, 0);
}

TEST(RunCommand, AHungProgramIsKilledAtTheDeadline) {
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_command({"sleep", "30"}, {0.3, 1000});
  const double took_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("killed"), std::string::npos) << r.error().message;
  EXPECT_LT(took_s, 10.0) << "the deadline held (not the program's 30 s)";
}

TEST(RunCommand, AMissingProgramIsAnError) {
  const auto r = run_command({"/nonexistent/chronyc", "tracking"});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("cannot run"), std::string::npos) << r.error().message;
  EXPECT_FALSE(run_command({}));
}

TEST(KernelClock, AnyoneMayReadIt) {
  const auto k = read_kernel_clock();
  ASSERT_TRUE(k) << k.error().message;
  EXPECT_GE(k.value().max_error_s, 0.0);
  EXPECT_FALSE(rtc_present("/nonexistent/rtc0"));
  EXPECT_FALSE(rtc_present("/dev/null/rtc0"));
  EXPECT_FALSE(rtc_present("/tmp")) << "a directory is not a clock";
}

}  // namespace
}  // namespace azt::linux_os
