// The noise log's appends (docs/calibration.md): lines added one after another, a new file made,
// and the refusals that keep the file one record a line.
#include "azt/linux/append_file.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "azt/linux/atomic_file.hpp"

namespace azt::linux_os {
namespace {

class AppendFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern =
        std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/azt_append_file_XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    ASSERT_NE(::mkdtemp(buffer.data()), nullptr);
    dir_ = buffer.data();
    path_ = dir_ + "/noise-log.jsonl";
  }
  void TearDown() override {
    ::unlink(path_.c_str());
    ::rmdir(dir_.c_str());
  }
  std::string dir_;
  std::string path_;
};

TEST_F(AppendFileTest, LinesFollowOneAnotherInANewFile) {
  ASSERT_TRUE(append_line(path_, R"({"y_factor_db":25.3})"));
  ASSERT_TRUE(append_line(path_, R"({"y_factor_db":25.1})"));
  EXPECT_EQ(read_file(path_).value(), "{\"y_factor_db\":25.3}\n{\"y_factor_db\":25.1}\n");
}

TEST_F(AppendFileTest, ALineWithANewlineOrTooLongIsRefusedAndNothingWritten) {
  const auto two = append_line(path_, "one\ntwo");
  ASSERT_FALSE(two);
  EXPECT_EQ(two.error().message, "a logged line holds a newline");
  EXPECT_FALSE(append_line(path_, std::string(kMaxAppendedLine + 1, 'x')));
  EXPECT_FALSE(read_file(path_));  // never created
}

TEST_F(AppendFileTest, AMissingDirectoryIsNamed) {
  const auto r = append_line(dir_ + "/no/such/log", "x");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("open for appending"), std::string::npos);
  EXPECT_NE(r.error().message.find("/no/such/log"), std::string::npos);
}

}  // namespace
}  // namespace azt::linux_os
