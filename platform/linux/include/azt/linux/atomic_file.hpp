#pragma once

#include <sys/types.h>

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "azt/util/result.hpp"

/// Crash-safe file replacement for runtime-saved state (config, calibration, park positions).
///
/// A save is: write `path.tmp.<pid>`, fsync it, keep the current file as `path.bak` (hard link, or
/// a temp copy renamed into place), rename the temp over `path`, fsync the directory. rename(2) is
/// atomic, so a kill -9 or power cut at any instant leaves either the old or the new file, never a
/// torn one. Nothing here throws; every failure names the step and strerror(errno).
namespace azt::linux_os {

/// The largest file read_file() accepts; runtime state files are kilobytes.
inline constexpr std::size_t kMaxReadBytes = std::size_t{4} * 1024 * 1024;

/// Atomically replaces `path` with `contents`, keeping the previous version as `path.bak`.
/// Uses the existing file's permission bits, or `new_file_mode` for a new file (the temp is 0600
/// until it is complete). On failure `path` is unchanged and the temp file is removed.
Result<bool> write_file_atomically(const std::string& path, std::string_view contents,
                                   mode_t new_file_mode = 0644);

/// Replaces `path` with `contents` atomically for its readers (a temp file renamed over it), but
/// neither fsynced nor backed up: for a file rewritten every second for other programs to poll
/// (azel.dat), where a power cut may lose the last second but must never show a torn file, and
/// an fsync a second would wear an SD card. The file is always kPublishedMode less the umask:
/// never the bits of what was at `path` before, nor of a link's target.
Result<bool> publish_file(const std::string& path, std::string_view contents);
inline constexpr mode_t kPublishedMode = 0644;

/// Removes the temp files that writes to `path` left behind when their process was killed
/// (`path.tmp.PID`, `path.bak.tmp.PID` of a PID that no longer runs); returns how many.
std::size_t remove_stale_temp_files(const std::string& path);

/// Reads the whole of `path`; fails beyond kMaxReadBytes.
Result<std::string> read_file(const std::string& path);

/// What load_with_backup() found.
struct LoadedText {
  std::string text;
  bool from_backup = false;
  std::string warning;  ///< non-empty when from_backup: why the primary file was not used
};

/// Reads `path` and checks it with `validate`; if it is missing, unreadable or invalid, falls back
/// to `path.bak` (which must also validate), reporting the primary's problem in `warning` for the
/// caller to log loudly. Fails, naming both problems, when neither file is usable.
Result<LoadedText> load_with_backup(const std::string& path,
                                    const std::function<Result<bool>(std::string_view)>& validate);

}  // namespace azt::linux_os
