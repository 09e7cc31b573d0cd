#pragma once
// Runs a well-kept tool and reads what it prints (chronyc): no shell, nothing on its
// standard input, its output bounded, and a deadline after which it is killed. It blocks until
// the program ends, so it runs on a worker thread, never on the event loop.

#include <cstddef>
#include <string>
#include <vector>

#include "azt/util/result.hpp"

namespace azt::linux_os {

struct CommandOutput {
  int exit_code = 0;  ///< the program's exit status (128 + N when signal N ended it)
  std::string out;    ///< standard output, cut at the byte limit
  std::string err;    ///< standard error, cut at the byte limit
};

struct CommandLimits {
  double timeout_s = 5.0;             ///< then the program is killed and this is an error
  std::size_t max_bytes = 64 * 1024;  ///< per stream; the rest is read and thrown away
};

/// Runs argv[0] (looked up in PATH) with `argv`. An error when it cannot be started or does not
/// end within the deadline; a nonzero exit status is not an error (the caller reads `err`).
Result<CommandOutput> run_command(const std::vector<std::string>& argv, CommandLimits limits = {});

}  // namespace azt::linux_os
