#pragma once
// `azeltrack serve`: one thread, one Boost.Asio io_context (docs/daemon.md). The control tick runs
// on a steady_timer re-armed at absolute deadlines; the protocol servers and the web console share
// the loop; SIGINT, SIGTERM and SIGHUP stop the motors and leave cleanly.

#include <functional>
#include <optional>
#include <string>

#include "config/config_store.hpp"

namespace boost::asio {
class io_context;
}  // namespace boost::asio

namespace azt::app {

struct DaemonOptions {
  std::string config_path;
  /// Stop after this many seconds (0: until a signal). For tests and benchmarks.
  double run_for_s = 0.0;
  /// Tests: the daemon's UTC (Unix seconds) when it starts, then running with the steady clock,
  /// so that what it computes of the sky does not depend on the hour it runs at. Unset: the
  /// system clock.
  std::optional<double> utc_start_unix_s;
  /// Software updates from the console (the package's unit sets both): the folder the uploaded
  /// package goes to for the root update helper, and the helper's status file. Empty: the
  /// console shows the version only.
  std::string update_inbox;
  std::string update_status;
  /// Tests: called on the loop once it runs, with the loop, to drive peers and inject faults.
  std::function<void(boost::asio::io_context&)> on_loop_started;
};

/// Runs until a signal (or run_for_s); returns the exit code. Throws UsageError when a server or
/// the antenna cannot be set up (named port, device, key), before any motor moves. Changes made
/// from the web console are saved through `store`. Every way out leaves the outputs safe: a
/// signal stops the motors first (exit 0); an exception that escapes a handler stops the
/// motors, releases the T/R chain and returns 1; a fatal signal (a crash) zeroes the PWM duty
/// through crash_safe_outputs.hpp; the drivers' destructors zero what they drive.
int run_daemon(ConfigStore& store, const DaemonOptions& options);

}  // namespace azt::app
