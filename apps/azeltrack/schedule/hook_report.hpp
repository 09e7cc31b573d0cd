#pragma once
// The words a finished schedule hook leaves in the journal and the console's recent events
// (docs/satellites.md "Hooks"): how it ended, then the first lines it printed. Its output is a
// stranger's bytes: made valid UTF-8 without control characters before it reaches a log line or
// the console's JSON.

#include <cstddef>
#include <string>

#include "azt/linux/child_process.hpp"

namespace azt::app {

/// "exited 0 in 0.21 s", "exited 3 in …", "ended by signal 9 in …", "killed after its 30 s
/// timeout", "stopped: the daemon is stopping", "did not run: /x: No such file or directory".
std::string hook_ending(const linux_os::ChildResult& result, double timeout_s);

/// Whether the hook ran and exited 0 in time.
bool hook_succeeded(const linux_os::ChildResult& result);

/// The first lines, joined by " | " and cut at `max_bytes` (on a character's boundary), with
/// "(+N bytes not kept)" when the output went on; "" when it printed nothing.
std::string hook_output(const linux_os::ChildResult& result, std::size_t max_bytes);

}  // namespace azt::app
