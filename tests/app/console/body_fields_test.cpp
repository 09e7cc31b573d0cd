// The console's request bodies (body_fields.hpp): each malformed field is a 400 naming it.
#include "console/body_fields.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "console/console_model.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

unsigned status_of(const std::function<void()>& read, std::string* field = nullptr) {
  try {
    read();
  } catch (const ApiError& e) {
    if (field != nullptr) *field = e.field();
    return e.status();
  }
  return 200;
}

TEST(BodyFields, NumbersAreFiniteAndPresent) {
  EXPECT_DOUBLE_EQ(body_number(json{{"az_deg", 12.5}}, "az_deg"), 12.5);
  std::string field;
  EXPECT_EQ(status_of([] { body_number(json{{"az_deg", "12"}}, "az_deg"); }, &field), 400u);
  EXPECT_EQ(field, "az_deg");
  EXPECT_EQ(status_of([] { body_number(json::object(), "el_deg"); }, &field), 400u);
  EXPECT_EQ(field, "el_deg");
  EXPECT_EQ(status_of([] {
              body_number(json{{"az_deg", std::numeric_limits<double>::infinity()}}, "az_deg");
            }),
            400u);
  EXPECT_FALSE(body_optional_number(json::object(), "ra_deg").has_value());
  EXPECT_DOUBLE_EQ(*body_optional_number(json{{"ra_deg", 1}}, "ra_deg"), 1.0);
}

TEST(BodyFields, WholeNumbersAreCheckedBeforeTheyAreNarrowed) {
  EXPECT_EQ(body_whole_number(json{{"park", 3}}, "park", 1, 4, "bad"), 3);
  // 2^32 + 1 would be slot 1 if it were narrowed first.
  EXPECT_EQ(status_of([] {
              body_whole_number(json{{"park", 4294967297ULL}}, "park", 1, 4, "m");
            }),
            400u);
  EXPECT_EQ(status_of([] { body_whole_number(json{{"park", 1.5}}, "park", 1, 4, "m"); }), 400u);
  EXPECT_EQ(status_of([] { body_whole_number(json{{"park", -1}}, "park", 1, 4, "m"); }), 400u);
}

TEST(BodyFields, TextIsAString) {
  EXPECT_EQ(body_text(json{{"name", "moon"}}, "name"), "moon");
  std::string field;
  EXPECT_EQ(status_of([] { body_text(json{{"name", 7}}, "name"); }, &field), 400u);
  EXPECT_EQ(field, "name");
}

}  // namespace
}  // namespace azt::app
