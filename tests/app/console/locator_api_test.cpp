// GET /api/locator's answers (the console's Setup page asks it while the operator types): the
// core's Maidenhead both ways, and a 400 naming the key for anything else.
#include "console/locator_api.hpp"

#include <gtest/gtest.h>

#include "console/console_model.hpp"

namespace azt::app {
namespace {

TEST(LocatorApi, ALocatorGivesTheCentreOfItsSquare) {
  const auto j = locator_json("grid=FN06HE");
  EXPECT_EQ(j["grid"], "FN06HE");
  EXPECT_NEAR(j["lat_deg"].get<double>(), 46.1875, 1e-9);
  EXPECT_NEAR(j["lon_deg"].get<double>(), -79.375, 1e-9);
}

TEST(LocatorApi, APositionGivesItsSixCharacterLocator) {
  const auto j = locator_json("lat=46.189&lon=-79.393");
  EXPECT_EQ(j["grid"], "FN06he");
  EXPECT_DOUBLE_EQ(j["lat_deg"].get<double>(), 46.189);
}

TEST(LocatorApi, BadQueriesAre400sNamingTheKey) {
  const auto refused = [](const std::string& query) -> std::string {
    try {
      (void)locator_json(query);
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400U) << query;
      return e.field();
    }
    ADD_FAILURE() << query << " was answered";
    return {};
  };
  EXPECT_EQ(refused("grid=ZZ99"), "grid");
  EXPECT_EQ(refused("grid="), "grid");
  EXPECT_EQ(refused("lat=46"), "lon");
  EXPECT_EQ(refused("lat=abc&lon=1"), "lat");
  EXPECT_EQ(refused("lat=1e999&lon=1"), "lat");
  EXPECT_EQ(refused("lat=91&lon=0"), "lat");
  EXPECT_EQ(refused(""), "lat");
}

}  // namespace
}  // namespace azt::app
