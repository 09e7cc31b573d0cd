#include "cli_error.hpp"

#include <iostream>

namespace azt::app {

void print_error(const std::string& message) {
  std::cerr << "azeltrack: error: " << message << '\n';
}

}  // namespace azt::app
