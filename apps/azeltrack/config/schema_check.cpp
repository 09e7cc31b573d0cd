// A value against its key's description: the one check the file loader and the console's
// settings share (config_schema.hpp). The words are the loader's: "must be 0 to 2".
#include <cmath>
#include <cstdint>

#include "azt/util/format_number.hpp"
#include "config/config_schema.hpp"

namespace azt::app {
namespace {

/// Whole numbers without an exponent ("1000000", not "1e+06"): ranges read as people write them.
std::string number_text(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15) {
    return std::to_string(static_cast<std::int64_t>(value));
  }
  return format_number(value);
}

bool in_range(const Range& r, double v) {
  const bool low = r.min_exclusive ? v > r.min : v >= r.min;
  const bool high = r.max_exclusive ? v < r.max : v <= r.max;
  return low && high;
}

std::string lower_bound_text(const Range& r) {
  return (r.min_exclusive ? "above " : "at least ") + number_text(r.min);
}

std::string upper_bound_text(const Range& r) {
  return (r.max_exclusive ? "below " : "at most ") + number_text(r.max);
}

std::string bounded_text(const Range& r) {
  const bool closed_range = !r.min_exclusive && !r.max_exclusive;
  if (closed_range && r.min == -r.max && r.max > 0.0) return "within ±" + number_text(r.max);
  if (closed_range) return number_text(r.min) + " to " + number_text(r.max);
  if (!r.min_exclusive) return number_text(r.min) + " to " + upper_bound_text(r);
  return lower_bound_text(r) + " and " + upper_bound_text(r);
}

/// "must hold 60 numbers", "must hold 1 to 8 strings", "must hold at most 8 integers".
std::optional<std::string> count_violation(const ItemCount& count, std::size_t n,
                                           std::string_view what) {
  const bool too_few = n < count.min;
  const bool too_many = count.max > 0 && n > count.max;
  if (!too_few && !too_many) return std::nullopt;
  std::string how_many;
  if (count.min == count.max) {
    how_many = std::to_string(count.min);
  } else if (count.min == 0) {
    how_many = "at most " + std::to_string(count.max);
  } else if (count.max == 0) {
    how_many = "at least " + std::to_string(count.min);
  } else {
    how_many = std::to_string(count.min) + " to " + std::to_string(count.max);
  }
  return "must hold " + how_many + " " + std::string(what);
}

std::optional<std::string> range_violation(const Range& range, double v) {
  if (in_range(range, v)) return std::nullopt;
  return "must be " + range_text(range);
}

std::optional<std::string> integer_violation(const KeySpec& spec, const toml::node& value) {
  if (!value.is_integer()) return "must be an integer";
  const auto v = *value.value<std::int64_t>();
  if (!spec.choices.empty()) {
    for (const auto& choice : spec.choices) {
      if (choice == std::to_string(v)) return std::nullopt;
    }
    return "must be " + choices_text(spec);
  }
  return range_violation(spec.range, static_cast<double>(v));
}

std::optional<std::string> number_violation(const KeySpec& spec, const toml::node& value) {
  if (!value.is_number()) return "must be a number";
  const double v = *value.value<double>();
  if (!std::isfinite(v)) return "must be a finite number";
  return range_violation(spec.range, v);
}

std::optional<std::string> choice_violation(const KeySpec& spec, const toml::node& value) {
  const auto* text = value.as_string();
  if (text == nullptr) return "must be a string";
  for (const auto& choice : spec.choices) {
    if (choice == text->get()) return std::nullopt;
  }
  return "must be " + choices_text(spec);
}

constexpr std::string_view kGpioLineRule = "must be a line number 0 to 1023, or \"CHIP:N\"";

/// A line number on [gpio] chip, or "CHIP:N" (a line on another chip).
std::optional<std::string> gpio_line_violation(const toml::node& value) {
  if (value.is_integer()) {
    const auto n = *value.value<std::int64_t>();
    if (n >= 0 && n <= 1023) return std::nullopt;
    return std::string(kGpioLineRule);
  }
  const auto* text = value.as_string();
  if (text == nullptr) return std::string(kGpioLineRule);
  const std::string& s = text->get();
  const auto colon = s.rfind(':');
  if (colon == std::string::npos || colon == 0) return std::string(kGpioLineRule);
  const std::string digits = s.substr(colon + 1);
  const bool number = !digits.empty() && digits.size() <= 4 &&
                      digits.find_first_not_of("0123456789") == std::string::npos;
  if (!number || std::stoi(digits) > 1023) return std::string(kGpioLineRule);
  return std::nullopt;
}

/// What a list holds, as its refusal says it; nullopt for a key that is not a list.
std::optional<std::string_view> item_word(KeyType type) {
  switch (type) {
    case KeyType::TextList:
      return "strings";
    case KeyType::NumberList:
      return "numbers";
    case KeyType::IntegerList:
      return "integers";
    case KeyType::Boolean:
    case KeyType::Integer:
    case KeyType::Number:
    case KeyType::Text:
    case KeyType::Choice:
    case KeyType::GpioLine:
      return std::nullopt;
  }
  return std::nullopt;
}

bool item_fits(KeyType list, const toml::node& item) {
  switch (list) {
    case KeyType::TextList:
      return item.is_string();
    case KeyType::NumberList:
      return item.is_number() && std::isfinite(*item.value<double>());
    case KeyType::IntegerList:
      return item.is_integer();
    case KeyType::Boolean:
    case KeyType::Integer:
    case KeyType::Number:
    case KeyType::Text:
    case KeyType::Choice:
    case KeyType::GpioLine:
      return false;
  }
  return false;
}

std::optional<std::string> list_violation(const KeySpec& spec, const toml::node& value) {
  if (spec.text_alone && value.is_string()) return count_violation(spec.items, 1, "strings");
  const toml::array* a = value.as_array();
  if (a == nullptr) return spec.text_alone ? "must be a string or an array" : "must be an array";
  const std::string what(item_word(spec.type).value_or("values"));
  for (const auto& item : *a) {
    if (!item_fits(spec.type, item)) return "must hold " + what;
    if (item.is_number() && !in_range(spec.range, *item.value<double>())) {
      return "must hold " + what + " " + range_text(spec.range);
    }
  }
  return count_violation(spec.items, a->size(), what);
}

}  // namespace

std::string range_text(const Range& range) {
  const bool has_min = std::isfinite(range.min);
  const bool has_max = std::isfinite(range.max);
  if (has_min && has_max) return bounded_text(range);
  if (has_min) return lower_bound_text(range);
  if (has_max) return upper_bound_text(range);
  return "";
}

std::string choices_text(const KeySpec& spec) {
  const bool quoted = spec.type != KeyType::Integer;
  std::string out;
  for (std::size_t i = 0; i < spec.choices.size(); ++i) {
    if (i > 0) out += i + 1 == spec.choices.size() ? " or " : ", ";
    out += quoted ? "\"" + std::string(spec.choices[i]) + "\"" : std::string(spec.choices[i]);
  }
  return out;
}

std::optional<std::string> key_violation(const KeySpec& spec, const toml::node& value) {
  switch (spec.type) {
    case KeyType::Boolean:
      return value.is_boolean() ? std::nullopt
                                : std::optional<std::string>("must be true or false");
    case KeyType::Integer:
      return integer_violation(spec, value);
    case KeyType::Number:
      return number_violation(spec, value);
    case KeyType::Text:
      return value.is_string() ? std::nullopt : std::optional<std::string>("must be a string");
    case KeyType::Choice:
      return choice_violation(spec, value);
    case KeyType::GpioLine:
      return gpio_line_violation(value);
    case KeyType::TextList:
    case KeyType::NumberList:
    case KeyType::IntegerList:
      return list_violation(spec, value);
  }
  return "has a type this program does not know";
}

}  // namespace azt::app
