#pragma once
// A key whose value is one of a few names ("relay", "gs232b"): read once, at the parser, into an
// enum, so the rest of the program switches on the enum and the compiler sees every case.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace azt::app {

template <typename Enum>
struct ConfigChoice {
  std::string_view name;
  Enum value;
};

template <typename Enum, std::size_t N>
using ConfigChoices = std::array<ConfigChoice<Enum>, N>;

/// The value named `name`; nullopt when no choice has that name.
template <typename Enum, std::size_t N>
std::optional<Enum> choose(const ConfigChoices<Enum, N>& choices, std::string_view name) {
  for (const auto& c : choices) {
    if (c.name == name) return c.value;
  }
  return std::nullopt;
}

/// The name of `value` as the configuration spells it.
template <typename Enum, std::size_t N>
std::string_view name_of(const ConfigChoices<Enum, N>& choices, Enum value) {
  for (const auto& c : choices) {
    if (c.value == value) return c.name;
  }
  return "?";
}

/// The names alone, in order: the configuration schema's list of what a key may be.
template <typename Enum, std::size_t N>
constexpr std::array<std::string_view, N> choice_names(const ConfigChoices<Enum, N>& choices) {
  std::array<std::string_view, N> names{};
  for (std::size_t i = 0; i < N; ++i) names[i] = choices[i].name;
  return names;
}

/// "\"a\", \"b\" or \"c\"", for the error that lists what is allowed.
template <typename Enum, std::size_t N>
std::string choice_list(const ConfigChoices<Enum, N>& choices) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) out += i + 1 == N ? " or " : ", ";
    out += "\"";
    out += choices[i].name;
    out += "\"";
  }
  return out;
}

}  // namespace azt::app
