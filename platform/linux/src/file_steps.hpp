#pragma once
// The steps every careful file write of the daemon takes (atomic_file.cpp, staged_file.cpp):
// whole writes through partial writes and EINTR, fsyncs that retry EINTR, the directory's fsync
// that makes a rename durable, and errors that name the step, the path and strerror(errno).
// Private to the Linux adapters.

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::linux_os {

inline std::string errno_text(int err) { return std::strerror(err); }

inline Error step_error(const std::string& step, const std::string& path, int err) {
  return fail(step + " '" + path + "': " + errno_text(err));
}

/// The directory holding `path`, for the final fsync.
inline std::string parent_directory(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

/// Writes all of `data`, retrying partial writes and EINTR. Returns 0 or an errno.
inline int write_all(int fd, std::string_view data) {
  const char* cursor = data.data();
  std::size_t left = data.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, cursor, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    cursor += n;
    left -= static_cast<std::size_t>(n);
  }
  return 0;
}

inline int fsync_retrying(int fd) {
  while (::fsync(fd) != 0) {
    if (errno != EINTR) return errno;
  }
  return 0;
}

/// fsyncs the directory holding `path`: a rename into it survives a power cut only then.
inline Result<bool> fsync_directory_of(const std::string& path) {
  const std::string dir = parent_directory(path);
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd < 0) return step_error("open directory for fsync", dir, errno);
  const int err = fsync_retrying(dir_fd);
  ::close(dir_fd);
  if (err != 0) return step_error("fsync directory", dir, err);
  return true;
}

}  // namespace azt::linux_os
