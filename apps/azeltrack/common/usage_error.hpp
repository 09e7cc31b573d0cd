#pragma once

#include <stdexcept>
#include <string>

namespace azt::app {

/// A bad argument or value from the user: reported as one line on stderr, exit code 2.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& what) : std::runtime_error(what) {}
};

/// Exit code for bad arguments (as argparse, CLI11 and most Unix tools use).
inline constexpr int kExitUsage = 2;
/// Exit code when the program could not do what was asked for another reason.
inline constexpr int kExitFailure = 1;

/// Prints "azeltrack: error: <message>" on stderr.
void print_error(const std::string& message);

/// Parses a finite decimal number given to `option`; throws UsageError otherwise
/// (CLI11 would accept "nan" and "inf").
double parse_number_option(const std::string& option, const std::string& text);

}  // namespace azt::app
