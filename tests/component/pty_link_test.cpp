// One daemon per pty name (pty_link.hpp): the link is held while its owner lives, a second
// claim is refused naming the holder's pid, and an owner removes only a link that is still its.
// flock(2) locks of two open(2)s conflict within one process too, so one test process plays
// both daemons.
#include "azt/linux/pty_link.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

class PtyLinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("azt-pty-link-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string link() const { return (dir_ / "gs232b").string(); }
  fs::path dir_;
};

TEST_F(PtyLinkTest, HeldLinkPointsAtTheTargetAndGoesWithItsOwner) {
  {
    auto held = PtyLink::claim(link(), "/dev/pts/98");
    ASSERT_TRUE(held) << held.error().message;
    EXPECT_EQ(fs::read_symlink(link()), "/dev/pts/98");
  }
  EXPECT_FALSE(fs::exists(fs::symlink_status(link())));
}

TEST_F(PtyLinkTest, SecondClaimIsRefusedNamingTheHolderAndLeavesTheLink) {
  auto first = PtyLink::claim(link(), "/dev/pts/98");
  ASSERT_TRUE(first) << first.error().message;
  auto second = PtyLink::claim(link(), "/dev/pts/99");
  ASSERT_FALSE(second);
  EXPECT_NE(second.error().message.find("in use by another azeltrack daemon (pid " +
                                        std::to_string(::getpid()) + ")"),
            std::string::npos)
      << second.error().message;
  EXPECT_EQ(fs::read_symlink(link()), "/dev/pts/98");
}

TEST_F(PtyLinkTest, ReleasedLinkCanBeClaimedAgain) {
  { ASSERT_TRUE(PtyLink::claim(link(), "/dev/pts/98")); }
  auto again = PtyLink::claim(link(), "/dev/pts/99");
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_EQ(fs::read_symlink(link()), "/dev/pts/99");
}

TEST_F(PtyLinkTest, StaleLinkOfADeadDaemonIsReplaced) {
  // A daemon killed with SIGKILL leaves its link; its lock died with it.
  fs::create_directories(dir_);
  fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::replace);
  fs::create_symlink("/dev/pts/97", link());
  auto held = PtyLink::claim(link(), "/dev/pts/98");
  ASSERT_TRUE(held) << held.error().message;
  EXPECT_EQ(fs::read_symlink(link()), "/dev/pts/98");
}

TEST_F(PtyLinkTest, LinkThatIsNoLongerOursStaysWhenTheOwnerGoes) {
  {
    auto held = PtyLink::claim(link(), "/dev/pts/98");
    ASSERT_TRUE(held);
    fs::remove(link());
    fs::create_symlink("/dev/pts/42", link());  // replaced by hand while we ran
  }
  EXPECT_EQ(fs::read_symlink(link()), "/dev/pts/42");
}

TEST_F(PtyLinkTest, FileInTheLinksPlaceIsNeverReplaced) {
  fs::create_directories(dir_);
  fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::replace);
  {
    std::FILE* f = std::fopen(link().c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fclose(f);
  }
  auto held = PtyLink::claim(link(), "/dev/pts/98");
  ASSERT_FALSE(held);
  EXPECT_NE(held.error().message.find("is not a symbolic link"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(link())));
}

}  // namespace
}  // namespace azt::linux_os
