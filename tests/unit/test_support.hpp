#pragma once

#include <gtest/gtest.h>

#include <string>

#include "azt/astro/time_scales.hpp"

namespace azt::test {

inline bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

/// A UTC instant from a calendar date that the test knows to be valid (fails the test if not).
inline astro::UtcInstant calendar(int y, int mo, int d, int h, int mi, double s) {
  auto r = astro::UtcInstant::from_calendar(y, mo, d, h, mi, s);
  EXPECT_TRUE(r.ok()) << r.error().message;
  return r.ok() ? *r : astro::UtcInstant{};
}

}  // namespace azt::test
