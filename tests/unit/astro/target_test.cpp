#include "azt/astro/target.hpp"

#include <gtest/gtest.h>

namespace azt::astro {
namespace {

TEST(ParseTarget, SunMoonAndCatalogue) {
  EXPECT_EQ(parse_target("sun")->kind, Target::Kind::Sun);
  EXPECT_EQ(parse_target("MOON")->kind, Target::Kind::Moon);
  auto cas = parse_target("casa");
  ASSERT_TRUE(cas.ok());
  EXPECT_EQ(cas->kind, Target::Kind::Source);
  EXPECT_EQ(cas->name, "Cassiopeia A");
  EXPECT_DOUBLE_EQ(cas->ra_deg, 350.85);
}

TEST(ParseTarget, RaDec) {
  auto t = parse_target("radec:83.633,22.0145");
  ASSERT_TRUE(t.ok()) << t.error().message;
  EXPECT_EQ(t->kind, Target::Kind::RaDec);
  EXPECT_DOUBLE_EQ(t->ra_deg, 83.633);
  EXPECT_DOUBLE_EQ(t->dec_deg, 22.0145);
  EXPECT_TRUE(parse_target("radec:0,-90").ok());
}

TEST(ParseTarget, ErrorsNameTheProblem) {
  for (const char* bad : {"radec:360,0", "radec:10,91", "radec:abc,1", "radec:1", "radec:1,2,3",
                          "radec:nan,0", "radec:", "jupiter", ""}) {
    auto t = parse_target(bad);
    EXPECT_FALSE(t.ok()) << bad;
    if (!t.ok()) {
      EXPECT_FALSE(t.error().message.empty()) << bad;
    }
  }
  EXPECT_NE(parse_target("jupiter").error().message.find("jupiter"), std::string::npos);
}

}  // namespace
}  // namespace azt::astro
