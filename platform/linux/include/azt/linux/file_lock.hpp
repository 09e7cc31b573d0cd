#pragma once

#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

/// An exclusive advisory lock (flock(2)) on a lock file, held until destruction. Serializes the
/// read-modify-write of a saved file between processes (the daemon and `azeltrack config set`);
/// the lock dies with its process, so a kill -9 never leaves it stuck.
class FileLock {
 public:
  /// Creates `lock_path` if needed (mode 0600) and waits up to `wait_s` for the lock, then fails
  /// with a message naming the file and the wait. Blocks the calling thread: the daemon calls it
  /// only on its worker thread (worker_thread.hpp), never on the event loop.
  static Result<FileLock> acquire(const std::string& lock_path, double wait_s);

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
