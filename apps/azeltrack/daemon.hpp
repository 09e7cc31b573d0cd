#pragma once
// `azeltrack serve`: one thread, one Boost.Asio io_context (DESIGN.md). The control tick runs on
// a steady_timer re-armed at absolute deadlines; the protocol servers and the web console share
// the loop; SIGINT, SIGTERM and SIGHUP stop the motors and leave cleanly.

#include <string>

#include "config_store.hpp"

namespace azt::app {

struct DaemonOptions {
  std::string config_path;
  /// Stop after this many seconds (0: until a signal). For tests and benchmarks.
  double run_for_s = 0.0;
};

/// Runs until a signal (or run_for_s); returns the exit code. Throws UsageError when a server or
/// the antenna cannot be set up (named port, device, key), before any motor moves. Changes made
/// from the web console are saved through `store`.
int run_daemon(ConfigStore& store, const DaemonOptions& options);

}  // namespace azt::app
