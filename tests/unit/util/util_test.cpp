#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "azt/util/format_number.hpp"
#include "azt/util/parse_number.hpp"
#include "azt/util/quote.hpp"

namespace azt {
namespace {

TEST(FormatNumber, ShortestRoundTrip) {
  EXPECT_EQ(format_number(46.189), "46.189");
  EXPECT_EQ(format_number(-79.393), "-79.393");
  EXPECT_EQ(format_number(10.0), "10");
  EXPECT_EQ(format_number(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(format_number(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(format_number(std::nan("")), "nan");
  for (double v : {1e-300, 123456.789e10, -0.0, 2460748.750800741}) {
    EXPECT_EQ(*parse_finite_double(format_number(v)), v) << v;
  }
}

TEST(Quote, QuotesAndCutsLongInput) {
  EXPECT_EQ(quote("FN06"), "\"FN06\"");
  EXPECT_EQ(quote(""), "\"\"");
  EXPECT_EQ(quote("abcdef", 3), "\"abc...\"");
  EXPECT_EQ(quote("abc", 3), "\"abc\"");
  EXPECT_EQ(quote(std::string(10000, 'x')).size(), 64u + 5u);
}

}  // namespace
}  // namespace azt
