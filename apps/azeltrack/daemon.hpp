#pragma once
// `azeltrack serve`: one thread, one Boost.Asio io_context (DESIGN.md). The control tick runs on
// a steady_timer re-armed at absolute deadlines; the protocol servers share the loop; SIGINT and
// SIGTERM stop the motors and leave cleanly.

#include <string>

#include "daemon_config.hpp"

namespace azt::app {

struct DaemonOptions {
  std::string config_path;
  /// Stop after this many seconds (0: until a signal). For tests and benchmarks.
  double run_for_s = 0.0;
};

/// Runs until SIGINT/SIGTERM (or run_for_s); returns the exit code. Throws UsageError when a
/// server or the antenna cannot be set up (named port, device, key), before any motor moves.
int run_daemon(const DaemonConfig& config, const DaemonOptions& options);

}  // namespace azt::app
