// The outer check of an uploaded package (docs/packaging.md): a real .deb made by dpkg-deb passes
// with its members named; anything else is refused with the first thing wrong, never read past
// its end.
#include "azt/software/deb_archive.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

namespace azt::software {
namespace {

std::string tiny_deb() {
  std::ifstream in(std::string(AZT_TEST_DATA_DIR) + "/software/azeltrack-test_0.1_all.deb",
                   std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string refusal(const std::string& bytes) {
  const auto r = check_deb_archive(bytes);
  return r ? "accepted" : r.error().message;
}

TEST(DebArchive, APackageMadeByDpkgDebPasses) {
  const std::string deb = tiny_deb();
  ASSERT_EQ(deb.size(), 804U) << "tests/data/software/README.md";
  const auto r = check_deb_archive(deb);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->format_version, "2.0");
  EXPECT_EQ(r->control_member, "control.tar.xz");
  EXPECT_EQ(r->data_member, "data.tar.xz");
  EXPECT_GT(r->data_bytes, 0U);
  EXPECT_LT(r->data_bytes, deb.size());
}

TEST(DebArchive, OtherFilesAreNotPackages) {
  for (const std::string& other :
       {std::string(), std::string("hello"), std::string("PK\x03\x04 a zip file"),
        std::string(804, '\0'), std::string("!<arch>\n")}) {
    EXPECT_NE(refusal(other).find("not a Debian package"), std::string::npos) << other;
  }
}

TEST(DebArchive, EveryCutIsRefusedWithoutReadingPastTheEnd) {
  const std::string deb = tiny_deb();
  for (std::size_t n = 0; n + 1 < deb.size(); ++n) {
    EXPECT_FALSE(check_deb_archive(deb.substr(0, n))) << "cut at " << n;
  }
}

TEST(DebArchive, MembersOutOfOrderOrMisnamedAreRefused) {
  std::string deb = tiny_deb();
  std::string renamed = deb;
  renamed.replace(8, 13, "debian-binarx");
  EXPECT_NE(refusal(renamed).find("first member is not debian-binary"), std::string::npos);

  std::string future = deb;
  future.replace(68, 3,
                 "3.0");  // debian-binary's body: after the 8-byte magic and its 60-byte header
  EXPECT_NE(refusal(future).find("format version"), std::string::npos) << refusal(future);

  std::string bad_size = deb;
  bad_size.replace(8 + 48, 4, "9x  ");
  EXPECT_NE(refusal(bad_size).find("size is not a decimal"), std::string::npos);

  std::string huge = deb;
  huge.replace(8 + 48, 10, "9999999999");
  EXPECT_NE(refusal(huge).find("runs past the end"), std::string::npos);

  std::string bad_magic = deb;
  bad_magic[8 + 58] = 'x';
  EXPECT_NE(refusal(bad_magic).find("header is malformed"), std::string::npos);
}

}  // namespace
}  // namespace azt::software
