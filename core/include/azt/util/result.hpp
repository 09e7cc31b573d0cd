#pragma once

#include <string>
#include <utility>
#include <variant>

namespace azt {

/// Why a fallible core call failed: a sentence for a human, no codes to decode.
struct Error {
  std::string message;
};

/// A value or an Error. The core never throws across a module boundary;
/// C++20 has no std::expected, so this is the small subset we need.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : data_(std::move(value)) {}      // NOLINT(google-explicit-constructor)
  Result(Error error) : data_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  [[nodiscard]] bool ok() const { return std::holds_alternative<T>(data_); }
  explicit operator bool() const { return ok(); }

  /// Precondition: ok().
  [[nodiscard]] const T& value() const& { return std::get<T>(data_); }
  [[nodiscard]] T& value() & { return std::get<T>(data_); }
  [[nodiscard]] T&& value() && { return std::get<T>(std::move(data_)); }
  const T& operator*() const& { return value(); }
  const T* operator->() const { return &value(); }

  /// Precondition: !ok().
  [[nodiscard]] const Error& error() const { return std::get<Error>(data_); }

 private:
  std::variant<T, Error> data_;
};

/// Shorthand for returning a failure: `return fail("latitude out of range");`.
inline Error fail(std::string message) { return Error{std::move(message)}; }

}  // namespace azt
