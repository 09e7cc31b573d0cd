// The root update helper's report (docs/packaging.md), as the daemon reads it for the Software
// page: every phase the helper writes, unknown keys skipped, and a bad value an error, not half a
// report.
#include "azt/software/update_status.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace azt::software {
namespace {

const std::string kSha(64, 'a');

TEST(UpdateStatus, AnInstallingReportIsRead) {
  const auto r = parse_update_status(
      "phase=installing\npercent=40\nmessage=Unpacking azeltrack (0.1.1) over (0.1.0)\n"
      "from=0.1.0\nto=0.1.1\nsha256=" +
      kSha + "\nsigner=azeltrack release key, FC4892F01AAC91A1\nat=1764241234\n");
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->phase, UpdatePhase::Installing);
  EXPECT_EQ(r->percent, 40);
  EXPECT_EQ(r->message, "Unpacking azeltrack (0.1.1) over (0.1.0)");
  EXPECT_EQ(r->from_version, "0.1.0");
  EXPECT_EQ(r->to_version, "0.1.1");
  EXPECT_EQ(r->sha256_hex, kSha);
  EXPECT_EQ(r->signer, "azeltrack release key, FC4892F01AAC91A1");
  EXPECT_EQ(r->at_unix_s, 1764241234);
  EXPECT_FALSE(finished(r->phase));
}

TEST(UpdateStatus, EveryPhaseHasItsName) {
  for (const auto phase : {UpdatePhase::Checking, UpdatePhase::Refused, UpdatePhase::Installing,
                           UpdatePhase::Installed, UpdatePhase::Failed}) {
    const auto r = parse_update_status("phase=" + std::string(to_string(phase)) + "\n");
    ASSERT_TRUE(r) << to_string(phase);
    EXPECT_EQ(r->phase, phase);
  }
  EXPECT_TRUE(finished(UpdatePhase::Refused));
  EXPECT_TRUE(finished(UpdatePhase::Installed));
  EXPECT_TRUE(finished(UpdatePhase::Failed));
  EXPECT_FALSE(finished(UpdatePhase::Checking));
}

TEST(UpdateStatus, UnknownKeysAndCrLfAreTolerated) {
  const auto r = parse_update_status("phase=refused\r\nlog=/var/log/x\r\nmessage=a=b\r\n\r\n");
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->phase, UpdatePhase::Refused);
  EXPECT_EQ(r->message, "a=b");
}

TEST(UpdateStatus, BadValuesMakeTheReportAnError) {
  for (const std::string& bad : std::vector<std::string>{
           "", "percent=10\n", "phase=done\n", "phase=installing\npercent=101\n",
           "phase=installing\npercent=-1\n", "phase=installing\npercent=4x\n",
           "phase=installing\nat=-5\n", "phase=installed\nsha256=ABC\n",
           "phase=installed\nsha256=" + std::string(64, 'G') + "\n", "phase=installed\nto=1.0 rm\n",
           "phase=installed\nfrom=<b>\n", "phase=installed\nno equals sign\n",
           "phase=installed\nmessage=" + std::string(2000, 'x') + "\n",
           std::string(17 * 1024, '\n')}) {
    EXPECT_FALSE(parse_update_status(bad)) << bad.substr(0, 60);
  }
  const auto r = parse_update_status("phase=installing\npercent=101\n");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().message, "update status line 2: bad percent");
}

}  // namespace
}  // namespace azt::software
