// A file written in pieces and published whole (platform/linux staged_file): no name in its
// folder until published, read back at any offset, the published file whole with its mode
// whatever the umask, a file that was at the path replaced, a link there replaced and never
// followed, and nothing left when it is abandoned.
#include "azt/linux/staged_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

class StagedFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("azt-staged-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  fs::path dir_;
};

TEST_F(StagedFileTest, HasNoNameUntilPublishedThenIsWholeWithItsMode) {
  auto file = StagedFile::create(dir_.string(), 0640);
  ASSERT_TRUE(file) << file.error().message;
  ASSERT_TRUE(file.value().append("!<arch>\n"));
  ASSERT_TRUE(file.value().append(std::string(100000, 'x')));
  EXPECT_TRUE(fs::is_empty(dir_));
  EXPECT_EQ(file->size(), 100008U);
  EXPECT_EQ(file->read_at(0, 8), "!<arch>\n");
  EXPECT_EQ(file->read_at(100000, 50), "xxxxxxxx") << "cut at the end";
  EXPECT_EQ(file->read_at(200000, 5), "");
  const mode_t old_umask = ::umask(077);  // the mode is set, not left to the umask
  const auto target = dir_ / "request.deb";
  const auto published = file.value().publish(target.string());
  ::umask(old_umask);
  ASSERT_TRUE(published) << published.error().message;
  EXPECT_EQ(read_bytes(target), "!<arch>\n" + std::string(100000, 'x'));
  struct stat st {};
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640U);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1)
      << "no temp name left";
}

TEST_F(StagedFileTest, ReplacesAFileOrALinkAtThePathNeverItsTarget) {
  const auto target = dir_ / "request.deb";
  const auto elsewhere = dir_ / "elsewhere";
  { std::ofstream(elsewhere) << "keep me"; }
  fs::create_symlink(elsewhere, target);
  auto file = StagedFile::create(dir_.string(), 0600);
  ASSERT_TRUE(file);
  ASSERT_TRUE(file.value().append("new"));
  ASSERT_TRUE(file.value().publish(target.string()));
  EXPECT_FALSE(fs::is_symlink(target));
  EXPECT_EQ(read_bytes(target), "new");
  EXPECT_EQ(read_bytes(elsewhere), "keep me");
}

TEST_F(StagedFileTest, AnAbandonedFileLeavesNothing) {
  {
    auto file = StagedFile::create(dir_.string(), 0600);
    ASSERT_TRUE(file);
    ASSERT_TRUE(file.value().append(std::string(4096, 'a')));
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(StagedFileTest, AMissingFolderIsAnErrorNamingIt) {
  const auto file = StagedFile::create((dir_ / "absent").string(), 0600);
  ASSERT_FALSE(file);
  EXPECT_NE(file.error().message.find("absent"), std::string::npos) << file.error().message;
}

}  // namespace
}  // namespace azt::linux_os
