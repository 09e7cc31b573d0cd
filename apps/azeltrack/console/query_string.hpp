#pragma once
// The query part of an API request's URL ("hours=6", "grid=FN06HE", "lat=46.2&lon=-79.4").

#include <optional>
#include <string>
#include <string_view>

namespace azt::app {

/// The raw value of `key` ("a=1&b=2"), the first if repeated; nullopt when absent. No percent
/// decoding: the API's values are numbers and locators.
std::optional<std::string> query_value(const std::string& query, std::string_view key);

}  // namespace azt::app
