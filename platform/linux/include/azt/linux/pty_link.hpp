#pragma once
// The path a PC program opens for one of the daemon's serial servers on a pseudo-terminal
// ("pty:gs232b" -> /run/azeltrack/gs232b -> /dev/pts/N), held by one daemon at a time: a second
// daemon configured with the same name would otherwise take the link over, so that Hamlib's
// rotctl reads the wrong antenna and reports success, and the first daemon's clients find
// nothing when the second one exits and removes it (docs/daemon.md "One daemon per name").

#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

class PtyLink {
 public:
  /// Locks `link` (flock(2) on "LINK.lock", never waiting: a held lock is an error naming the
  /// holder's pid, as a port in use is) and points it at `target`, replacing only a stale
  /// symbolic link, never a file or device. The lock dies with the process, so a daemon killed
  /// with SIGKILL leaves a link the next one may replace.
  static Result<PtyLink> claim(const std::string& link, const std::string& target);

  PtyLink(PtyLink&& other) noexcept;
  PtyLink& operator=(PtyLink&& other) noexcept;
  PtyLink(const PtyLink&) = delete;
  PtyLink& operator=(const PtyLink&) = delete;
  /// Removes the link only if it still points at our target, then drops the lock.
  ~PtyLink();

  [[nodiscard]] const std::string& path() const { return link_; }

 private:
  PtyLink(int lock_fd, std::string link, std::string target)
      : lock_fd_(lock_fd), link_(std::move(link)), target_(std::move(target)) {}
  void release();

  int lock_fd_ = -1;
  std::string link_;
  std::string target_;
};

}  // namespace azt::linux_os
