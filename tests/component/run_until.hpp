#pragma once
// The component tests' wait: the real Asio loop runs in short slices until what the test waits
// for has happened, or a bound passes (no sleeping and hoping: the condition decides).

#include <chrono>

#include "azt/linux/asio.hpp"

namespace azt::linux_os {

/// Runs the loop until `done` or 5 s pass; false on timeout.
template <typename Done>
bool run_until(boost::asio::io_context& io, Done done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!done() && std::chrono::steady_clock::now() < end) {
    io.run_for(std::chrono::milliseconds(10));
    io.restart();
  }
  return done();
}

}  // namespace azt::linux_os
