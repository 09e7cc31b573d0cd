#pragma once

#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

/// An exclusive advisory lock (flock(2)) on a lock file, held until destruction. Serializes the
/// read-modify-write of a saved file between processes (the daemon and `azeltrack config set`);
/// the lock dies with its process, so a kill -9 never leaves it stuck.
class FileLock {
 public:
  /// Creates `lock_path` if needed and waits for the lock.
  static Result<FileLock> acquire(const std::string& lock_path);

  FileLock(FileLock&& other) noexcept;
  FileLock& operator=(FileLock&& other) noexcept;
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  ~FileLock();

 private:
  explicit FileLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace azt::linux_os
