#include "azt/linux/append_file.hpp"

#include "file_steps.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <string>

#include "azt/linux/unique_fd.hpp"

namespace azt::linux_os {

namespace {

/// One write of O_APPEND, then fsync.
Result<bool> append_record(const std::string& path, std::string_view record) {
  const UniqueFd fd(::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644));
  if (!fd.valid()) return step_error("open for appending", path, errno);
  if (const int err = write_all(fd.get(), record); err != 0)
    return step_error("append to", path, err);
  if (const int err = fsync_retrying(fd.get()); err != 0) return step_error("fsync", path, err);
  return true;
}

}  // namespace

Result<bool> append_line(const std::string& path, std::string_view line) {
  if (line.find('\n') != std::string_view::npos) return fail("a logged line holds a newline");
  if (line.size() > kMaxAppendedLine) return fail("a logged line is over 64 KiB");
  std::string record(line);
  record.push_back('\n');
  return append_record(path, record);
}

Result<bool> append_lines(const std::string& path, std::string_view lines) {
  if (lines.empty()) return true;
  if (lines.back() != '\n') return fail("appended lines must end in a newline");
  if (lines.size() > kMaxAppendedBlock) return fail("appended lines are over 8 MiB");
  return append_record(path, lines);
}

}  // namespace azt::linux_os
