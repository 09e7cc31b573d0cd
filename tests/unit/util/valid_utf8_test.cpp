#include "azt/util/valid_utf8.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <random>
#include <string>

namespace azt {
namespace {

const std::string kFffd = "\xEF\xBF\xBD";

TEST(ValidUtf8, WellFormedTextIsUnchanged) {
  for (const std::string s : {"", "ISS (ZARYA)", "caf\xC3\xA9", "\xE2\x82\xAC 10\xC2\xB0",
                              "\xF0\x9F\x93\xA1 dish", "\xEF\xBF\xBD"}) {
    EXPECT_TRUE(is_valid_utf8(s)) << s;
    EXPECT_EQ(valid_utf8(s), s);
  }
}

TEST(ValidUtf8, Latin1AndStrayBytesBecomeReplacementCharacters) {
  // The cases: a Latin-1 Host header and catalogue name.
  EXPECT_EQ(valid_utf8("caf\xE9"), "caf" + kFffd);
  EXPECT_EQ(valid_utf8("ISS Z\xE9RYA"), "ISS Z" + kFffd + "RYA");
  EXPECT_EQ(valid_utf8("\xFF"), kFffd);
  EXPECT_FALSE(is_valid_utf8("\xFF"));
}

TEST(ValidUtf8, OverlongsSurrogatesAndTooLargeAreRefused) {
  EXPECT_EQ(valid_utf8("\xC0\xAF"), kFffd + kFffd);              // overlong '/': C0 is never a lead
  EXPECT_EQ(valid_utf8("\xE0\x80\xAF"), kFffd + kFffd + kFffd);  // overlong, 3 bytes
  EXPECT_EQ(valid_utf8("\xED\xA0\x80"), kFffd + kFffd + kFffd);  // U+D800, a surrogate
  EXPECT_EQ(valid_utf8("\xF4\x90\x80\x80"), kFffd + kFffd + kFffd + kFffd);  // > U+10FFFF
}

TEST(ValidUtf8, ATruncatedSequenceIsOneReplacement) {
  // Maximal subpart: E2 82 is the start of a valid 3-byte sequence, cut short.
  EXPECT_EQ(valid_utf8("a\xE2\x82"), "a" + kFffd);
  EXPECT_EQ(valid_utf8("\xE2\x82z"), kFffd + "z");
  EXPECT_EQ(valid_utf8("\xF0\x9F\x93"), kFffd);
}

TEST(ValidUtf8, RandomBytesAlwaysGiveTextThatJsonAccepts) {
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<int> length(0, 40);
  for (int i = 0; i < 20000; ++i) {
    std::string raw(static_cast<std::size_t>(length(rng)), '\0');
    for (auto& c : raw) c = static_cast<char>(byte(rng));
    const std::string clean = valid_utf8(raw);
    ASSERT_TRUE(is_valid_utf8(clean));
    // nlohmann::json's strict dump throws on invalid UTF-8: it must not on the cleaned text.
    ASSERT_NO_THROW((void)nlohmann::json(clean).dump());
    ASSERT_EQ(valid_utf8(clean), clean);  // idempotent
  }
}

}  // namespace
}  // namespace azt
