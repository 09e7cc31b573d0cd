// The element-age verdict: fresh, stale past stale_days, refused past refuse_days, either way.
#include "azt/orbit/element_age.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::orbit {
namespace {

TEST(ElementAge, FreshStaleRefusedByTheLimits) {
  const ElementAgeLimits limits{14.0, 60.0};
  EXPECT_EQ(judge_element_age(0.0, limits), ElementAge::Fresh);
  EXPECT_EQ(judge_element_age(14.0, limits), ElementAge::Fresh);
  EXPECT_EQ(judge_element_age(14.1, limits), ElementAge::Stale);
  EXPECT_EQ(judge_element_age(60.0, limits), ElementAge::Stale);
  EXPECT_EQ(judge_element_age(60.1, limits), ElementAge::Refused);
  EXPECT_EQ(judge_element_age(-61.0, limits), ElementAge::Refused);
  EXPECT_EQ(judge_element_age(std::nan(""), limits), ElementAge::Refused);
}

TEST(ElementAge, TheRefusalSaysWhyAndWhatToDo) {
  const ElementAgeLimits limits{14.0, 60.0};
  EXPECT_EQ(element_age_refusal("ISS", 30.0, limits), "");
  EXPECT_EQ(element_age_refusal("ISS", 1001.04, limits),
            "the elements of ISS are 1001.0 days from their epoch (beyond [satellites] "
            "refuse_days = 60): not tracked; fetch fresh ones");
  EXPECT_NE(element_age_refusal("X", -75.25, limits).find("-75.3 days"), std::string::npos);
}

}  // namespace
}  // namespace azt::orbit
