#pragma once
// A log the daemon keeps over time (the noise measurements' log, docs/calibration.md): each
// record one line appended to a file under the state directory. The line goes in with one write
// of O_APPEND (a second daemon or a reader never sees two lines interleaved or half a line from
// a write that succeeded), then fsync: a measurement logged is not lost to a power cut. A line
// must not hold a newline of its own. Blocking: run it off the event loop.

#include <string>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::linux_os {

/// The longest line append_line() takes.
inline constexpr std::size_t kMaxAppendedLine = 64 * 1024;

/// Appends `line` and a newline to `path` (created 0644 less the umask when missing). Fails,
/// naming the step, on a line with a newline or over kMaxAppendedLine, or an I/O error.
Result<bool> append_line(const std::string& path, std::string_view line);

}  // namespace azt::linux_os
