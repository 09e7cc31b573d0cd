#pragma once
// Runs a program the operator named (a schedule hook, docs/satellites.md "Hooks") and waits for
// it, bounded in every way a stranger's program can misbehave: no shell, an environment given in
// full, nothing on its standard input, its own process group (so a timeout reaches whatever it
// started), no descriptor of ours besides its output pipe, its output kept only at its start and
// the rest read and counted so a flood never blocks it, and a deadline after which the group gets
// SIGTERM and, 2 s later, SIGKILL. run_child blocks until the program is reaped, so it runs on a
// thread of its own, never on the event loop; a ChildStop ends it early (the daemon's shutdown).

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <vector>

#include "azt/linux/unique_fd.hpp"

namespace azt::linux_os {

struct ChildSpec {
  std::vector<std::string> argv;  ///< argv[0] is the program's path, run as it is (no PATH search)
  std::vector<std::string> env;   ///< "NAME=value": the program's whole environment
  double timeout_s = 30.0;        ///< then SIGTERM to its process group
  double kill_after_s = 2.0;      ///< after SIGTERM, SIGKILL to the group
  std::size_t max_lines = 10;     ///< output kept: at most this many lines …
  std::size_t max_bytes = 2048;   ///< … and this many bytes
};

struct ChildResult {
  std::string spawn_error;  ///< not empty: the program never ran ("…: No such file or directory")
  pid_t pid = 0;            ///< the program's process id (reaped when run_child returns)
  int exit_code = -1;       ///< its exit status, or -1 when a signal ended it
  int signal = 0;           ///< the signal that ended it, or 0
  bool timed_out = false;   ///< killed at the deadline
  bool stopped = false;     ///< killed by a ChildStop
  double duration_s = 0.0;  ///< from its start until it was reaped
  std::string first_lines;  ///< stdout and stderr merged, as written, cut at the limits
  std::size_t dropped_bytes = 0;  ///< output read after the limits and thrown away
};

/// Ends a run_child early from another thread: the program's process group gets SIGKILL at once.
class ChildStop {
 public:
  ChildStop();
  void stop() const;  ///< safe from any thread, any number of times
  [[nodiscard]] int fd() const { return fd_.get(); }

 private:
  UniqueFd fd_;  ///< an eventfd that becomes readable on stop()
};

/// Runs `spec` and waits until it has ended and been reaped (see above). After the program
/// itself ends, what it started and left running is left alone, and no longer read.
ChildResult run_child(const ChildSpec& spec, const ChildStop* stop = nullptr);

}  // namespace azt::linux_os
