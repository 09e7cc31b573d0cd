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

/// The most append_lines() takes at once: an imported scan log (4 MiB) with room to spare.
inline constexpr std::size_t kMaxAppendedBlock = std::size_t{8} * 1024 * 1024;

/// Appends `lines` (whole lines, each ending in a newline) to `path` in one write of O_APPEND and
/// one fsync: a scan's rows of the scan log go in together or not at all. Fails, naming the
/// step, on text that does not end in a newline or is over kMaxAppendedBlock, or an I/O error.
Result<bool> append_lines(const std::string& path, std::string_view lines);

}  // namespace azt::linux_os
