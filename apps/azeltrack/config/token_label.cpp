#include "config/token_label.hpp"

namespace azt::app {

std::optional<std::string> token_label_problem(const std::string& label) {
  constexpr std::size_t kMaxLabel = 40;
  if (label.empty() || label.size() > kMaxLabel) return "must be 1 to 40 characters";
  const bool plain = label.find_first_not_of(
                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                         "0123456789 ._-") == std::string::npos;
  if (!plain) return "may hold letters, digits, spaces, '.', '_' and '-' only";
  return std::nullopt;
}

}  // namespace azt::app
