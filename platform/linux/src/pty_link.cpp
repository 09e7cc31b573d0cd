#include "azt/linux/pty_link.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

#include "azt/linux/runtime_dir.hpp"

namespace azt::linux_os {
namespace {

/// The pid the holder wrote into the lock file, for the error ("" when unreadable).
std::string holder_of(int fd) {
  std::array<char, 32> text{};
  const auto n = ::pread(fd, text.data(), text.size() - 1, 0);
  if (n <= 0) return "";
  std::string pid(text.data(), static_cast<std::size_t>(n));
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.find_first_not_of("0123456789") == std::string::npos ? pid : "";
}

void write_pid(int fd) {
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) == 0) {
    // The pid is only for another daemon's error message: a short write loses nothing.
    [[maybe_unused]] const auto n = ::pwrite(fd, pid.data(), pid.size(), 0);
  }
}

/// Opens and locks "LINK.lock" without waiting; the fd, or an error naming the holder.
Result<int> lock_link(const std::string& link) {
  const std::string lock_path = link + ".lock";
  // 0600 and O_NOFOLLOW, in the daemon's own directory: nobody else's link is followed. A lock
  // file another user made (a daemon once run as root) is still locked read-only.
  int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
  if (fd < 0 && errno == EACCES) fd = ::open(lock_path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return fail("cannot open the lock " + lock_path + ": " + std::strerror(errno));
  while (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    if (err == EINTR) continue;
    const std::string pid = holder_of(fd);
    ::close(fd);
    if (err != EWOULDBLOCK) return fail("cannot lock " + lock_path + ": " + std::strerror(err));
    return fail(link + " is in use by another azeltrack daemon" +
                (pid.empty() ? std::string() : " (pid " + pid + ")") +
                ": give this one other pty names, or stop that one");
  }
  write_pid(fd);
  return fd;
}

Result<bool> make_link(const std::string& link, const std::string& target) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path path(link);
  const auto status = fs::symlink_status(path, ec);
  if (fs::exists(status)) {
    if (!fs::is_symlink(status)) return fail(link + " exists and is not a symbolic link");
    fs::remove(path, ec);  // a link a daemon no longer running left behind (we hold the lock)
  }
  fs::create_symlink(target, path, ec);
  if (ec) return fail("cannot link " + link + ": " + ec.message());
  return true;
}

}  // namespace

Result<PtyLink> PtyLink::claim(const std::string& link, const std::string& target) {
  const std::filesystem::path path(link);
  if (path.has_parent_path()) {
    if (auto ok = ensure_private_dir(path.parent_path().string()); !ok) return ok.error();
  }
  auto fd = lock_link(link);
  if (!fd) return fd.error();
  if (auto linked = make_link(link, target); !linked) {
    ::close(*fd);
    return linked.error();
  }
  return PtyLink(*fd, link, target);
}

PtyLink::PtyLink(PtyLink&& other) noexcept
    : lock_fd_(std::exchange(other.lock_fd_, -1)),
      link_(std::move(other.link_)),
      target_(std::move(other.target_)) {}

PtyLink& PtyLink::operator=(PtyLink&& other) noexcept {
  if (this != &other) {
    release();
    lock_fd_ = std::exchange(other.lock_fd_, -1);
    link_ = std::move(other.link_);
    target_ = std::move(other.target_);
  }
  return *this;
}

PtyLink::~PtyLink() { release(); }

void PtyLink::release() {
  if (lock_fd_ < 0) return;
  std::error_code ec;
  // Someone else's link (replaced by hand, or by a daemon that ignored the lock) stays.
  if (std::filesystem::read_symlink(link_, ec) == target_ && !ec) {
    std::filesystem::remove(link_, ec);
  }
  ::close(lock_fd_);  // closing releases the flock; the empty-of-meaning lock file stays
  lock_fd_ = -1;
}

}  // namespace azt::linux_os
