#include "console/body_fields.hpp"

#include <cmath>

#include "console/console_model.hpp"

namespace azt::app {

using json = nlohmann::json;

double body_number(const json& body, const std::string& key) {
  const auto it = body.find(key);
  if (it == body.end()) throw ApiError(400, key, key + " is required");
  if (!it->is_number()) throw ApiError(400, key, key + " must be a number");
  const double v = it->get<double>();
  if (!std::isfinite(v)) throw ApiError(400, key, key + " must be finite");
  return v;
}

std::optional<double> body_optional_number(const json& body, const std::string& key) {
  if (!body.contains(key)) return std::nullopt;
  return body_number(body, key);
}

std::int64_t body_whole_number(const json& body, const std::string& key, std::int64_t lo,
                               std::int64_t hi, const std::string& message) {
  const auto it = body.find(key);
  if (it == body.end()) throw ApiError(400, key, message);
  if (it->is_number_unsigned()) {
    const auto v = it->get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(hi) || static_cast<std::int64_t>(v) < lo) {
      throw ApiError(400, key, message);
    }
    return static_cast<std::int64_t>(v);
  }
  if (!it->is_number_integer()) throw ApiError(400, key, message);
  const auto v = it->get<std::int64_t>();
  if (v < lo || v > hi) throw ApiError(400, key, message);
  return v;
}

std::string body_text(const json& body, const std::string& key) {
  const auto it = body.find(key);
  if (it == body.end() || !it->is_string()) throw ApiError(400, key, key + " must be a string");
  return it->get<std::string>();
}

}  // namespace azt::app
