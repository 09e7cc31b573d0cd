#pragma once
// The console's request bodies read field by field: a missing or ill-typed field is an ApiError
// (400) naming it, so the page marks the field and the station changes nothing.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace azt::app {

/// A finite number (400 when missing, not a number, or not finite).
double body_number(const nlohmann::json& body, const std::string& key);
/// As body_number, when present.
std::optional<double> body_optional_number(const nlohmann::json& body, const std::string& key);
/// An integer field in [lo, hi], checked before it is narrowed: 4294967297 is refused, never
/// taken for 1. nlohmann keeps large positives as unsigned, so both are read. `message` on any
/// failure.
std::int64_t body_whole_number(const nlohmann::json& body, const std::string& key, std::int64_t lo,
                               std::int64_t hi, const std::string& message);
/// A string field (400 when missing or not a string).
std::string body_text(const nlohmann::json& body, const std::string& key);

}  // namespace azt::app
