#include "common/usage_error.hpp"

#include <iostream>

#include "azt/util/parse_number.hpp"

namespace azt::app {

void print_error(const std::string& message) {
  std::cerr << "azeltrack: error: " << message << '\n';
}

// Here rather than beside a command: every command and the configuration readers use it.
double parse_number_option(const std::string& option, const std::string& text) {
  auto value = parse_finite_double(text);
  if (!value) throw UsageError(option + ": '" + text + "' is not a finite decimal number");
  return *value;
}

}  // namespace azt::app
