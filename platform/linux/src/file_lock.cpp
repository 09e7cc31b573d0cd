#include "azt/linux/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>
#include <utility>

namespace azt::linux_os {

Result<FileLock> FileLock::acquire(const std::string& lock_path, double wait_s) {
  // 0600: the lock file says nothing, but nobody else needs to open it.
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
  if (fd < 0) return fail("open lock file '" + lock_path + "': " + std::strerror(errno));
  // Polled without blocking in flock(2) itself, so the wait is bounded whoever holds the lock.
  constexpr auto kPoll = std::chrono::milliseconds(20);
  const auto give_up = std::chrono::steady_clock::now() +
                       std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(wait_s));
  while (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    if (err == EINTR) continue;
    if (err != EWOULDBLOCK || std::chrono::steady_clock::now() >= give_up) {
      ::close(fd);
      if (err == EWOULDBLOCK) {
        char wait[32];
        std::snprintf(wait, sizeof wait, "%.1f", wait_s);
        return fail("'" + lock_path + "' is held by another program for more than " + wait +
                    " s: nothing was saved, try again");
      }
      return fail("lock '" + lock_path + "': " + std::strerror(err));
    }
    std::this_thread::sleep_for(kPoll);
  }
  return FileLock(fd);
}

FileLock::FileLock(FileLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

FileLock& FileLock::operator=(FileLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

FileLock::~FileLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

}  // namespace azt::linux_os
