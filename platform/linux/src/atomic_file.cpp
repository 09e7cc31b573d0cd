#include "azt/linux/atomic_file.hpp"

#include "file_steps.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

namespace azt::linux_os {
namespace {

/// Closes a descriptor on scope exit unless released.
class FdGuard {
 public:
  explicit FdGuard(int fd) : fd_(fd) {}
  FdGuard(const FdGuard&) = delete;
  FdGuard& operator=(const FdGuard&) = delete;
  ~FdGuard() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] int get() const { return fd_; }
  /// Closes now and reports close(2)'s errno (0 on success); a failed close can mean lost data.
  int close_now() {
    const int fd = std::exchange(fd_, -1);
    if (fd < 0) return 0;
    return ::close(fd) == 0 ? 0 : errno;
  }

 private:
  int fd_;
};

/// Creates `temp` (O_EXCL: never adopts a stranger's file), writes `contents`, applies `mode`,
/// fsyncs and closes. On failure removes whatever it created.
Result<bool> write_durable_temp(const std::string& temp, std::string_view contents, mode_t mode) {
  ::unlink(temp.c_str());  // a stale temp from a killed earlier run with a recycled pid
  // 0600 while it is being written: a temp left by a kill -9 holds the whole file (the password
  // hash among it) and must not be readable by others even if the file itself is.
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) return step_error("create temp file", temp, errno);
  FdGuard guard(fd);
  auto fail_and_remove = [&](const std::string& step, int err) -> Result<bool> {
    guard.close_now();
    ::unlink(temp.c_str());
    return step_error(step, temp, err);
  };
  if (const int err = write_all(fd, contents); err != 0) {
    return fail_and_remove("write temp file", err);
  }
  if (const int err = fsync_retrying(fd); err != 0) return fail_and_remove("fsync temp file", err);
  // Only now the old file's bits (or 0644), exactly: open() applied the umask.
  if (::fchmod(fd, mode) != 0) return fail_and_remove("set mode of temp file", errno);
  if (const int err = guard.close_now(); err != 0) return fail_and_remove("close temp file", err);
  return true;
}

/// Makes `backup` name the current contents of `path` without ever exposing a partial backup:
/// hard-link (or, where links are unsupported, copy) to a temp name, then rename over `backup`.
Result<bool> refresh_backup(const std::string& path, const std::string& backup,
                            const std::string& backup_temp, mode_t mode) {
  ::unlink(backup_temp.c_str());
  if (::link(path.c_str(), backup_temp.c_str()) != 0) {
    const int link_err = errno;
    if (link_err != EPERM && link_err != EXDEV && link_err != EMLINK && link_err != ENOTSUP &&
        link_err != EOPNOTSUPP) {
      return step_error("hard-link backup of", path, link_err);
    }
    // EPERM is also what link(2) says for a directory; read_file refuses those, so that fails too.
    auto old_contents = read_file(path);
    if (!old_contents.ok()) {
      return fail("copy backup: " + old_contents.error().message +
                  " (link failed: " + errno_text(link_err) + ")");
    }
    auto copied = write_durable_temp(backup_temp, *old_contents, mode);
    if (!copied.ok()) return copied;
  }
  if (::rename(backup_temp.c_str(), backup.c_str()) != 0) {
    const int err = errno;
    ::unlink(backup_temp.c_str());
    return step_error("rename backup into place as", backup, err);
  }
  return true;
}

}  // namespace

Result<bool> write_file_atomically(const std::string& path, std::string_view contents,
                                   mode_t new_file_mode) {
  if (path.empty()) return fail("write_file_atomically: empty path");
  const std::string pid = std::to_string(::getpid());
  const std::string temp = path + ".tmp." + pid;
  const std::string backup = path + ".bak";
  const std::string backup_temp = backup + ".tmp." + pid;

  struct stat old_stat {};
  bool had_old = false;
  mode_t mode = new_file_mode;
  if (::stat(path.c_str(), &old_stat) == 0) {
    if (!S_ISREG(old_stat.st_mode)) return fail("'" + path + "' exists and is not a regular file");
    had_old = true;
    mode = old_stat.st_mode & 07777;
  } else if (errno != ENOENT) {
    return step_error("stat", path, errno);
  }

  auto written = write_durable_temp(temp, contents, mode);
  if (!written.ok()) return written;

  if (had_old) {
    auto backed_up = refresh_backup(path, backup, backup_temp, mode);
    if (!backed_up.ok()) {
      ::unlink(temp.c_str());
      return backed_up;
    }
  }

  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    return step_error("rename temp file over", path, err);
  }

  // Make both renames durable: without this a power cut may resurrect the old directory entry.
  return fsync_directory_of(path);
}

Result<bool> publish_file(const std::string& path, std::string_view contents) {
  if (path.empty()) return fail("publish_file: empty path");
  // A fixed mode, never the old file's: stat() of a planted symlink would have copied its
  // target's bits, setuid included. open() takes the umask off 0644, and rename()
  // replaces a link at `path` itself, never its target.
  const std::string temp = path + ".tmp." + std::to_string(::getpid());
  ::unlink(temp.c_str());
  const int fd =
      ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, kPublishedMode);
  if (fd < 0) return step_error("create temp file", temp, errno);
  FdGuard guard(fd);
  int err = write_all(fd, contents);
  if (const int close_err = guard.close_now(); err == 0) err = close_err;
  if (err == 0 && ::rename(temp.c_str(), path.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(temp.c_str());
    return step_error("publish", path, err);
  }
  return true;
}

Result<std::string> read_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return step_error("open", path, errno);
  FdGuard guard(fd);
  struct stat st {};
  if (::fstat(fd, &st) != 0) return step_error("stat", path, errno);
  if (!S_ISREG(st.st_mode)) return fail("'" + path + "' is not a regular file");
  if (static_cast<std::size_t>(st.st_size) > kMaxReadBytes) {
    return fail("'" + path + "' is larger than " + std::to_string(kMaxReadBytes) + " bytes");
  }
  std::string text;
  text.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      return step_error("read", path, errno);
    }
    if (n == 0) break;
    if (text.size() + static_cast<std::size_t>(n) > kMaxReadBytes) {
      return fail("'" + path + "' is larger than " + std::to_string(kMaxReadBytes) + " bytes");
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

Result<LoadedText> load_with_backup(const std::string& path,
                                    const std::function<Result<bool>(std::string_view)>& validate) {
  std::string primary_problem;
  if (auto primary = read_file(path); primary.ok()) {
    auto valid = validate(*primary);
    if (valid.ok()) return LoadedText{std::move(primary).value(), false, {}};
    primary_problem = "'" + path + "' is invalid: " + valid.error().message;
  } else {
    primary_problem = primary.error().message;
  }

  const std::string backup = path + ".bak";
  auto fallback = read_file(backup);
  if (!fallback.ok()) {
    return fail(primary_problem + "; and no usable backup: " + fallback.error().message);
  }
  auto valid = validate(*fallback);
  if (!valid.ok()) {
    return fail(primary_problem + "; and backup '" + backup +
                "' is invalid too: " + valid.error().message);
  }
  return LoadedText{std::move(fallback).value(), true,
                    primary_problem + "; using backup '" + backup + "' instead"};
}

std::size_t remove_stale_temp_files(const std::string& path) {
  const std::string dir = parent_directory(path);
  const auto slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  std::size_t removed = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    for (const std::string& stem : {base + ".tmp.", base + ".bak.tmp."}) {
      if (name.rfind(stem, 0) != 0) continue;
      const std::string pid_text = name.substr(stem.size());
      if (pid_text.empty() || pid_text.size() > 9 ||
          pid_text.find_first_not_of("0123456789") != std::string::npos) {
        continue;
      }
      // A writer that is still alive (a `config set` saving right now) keeps its temp.
      const auto pid = static_cast<pid_t>(std::stol(pid_text));
      if (pid == ::getpid() || (::kill(pid, 0) == 0 || errno == EPERM)) continue;
      if (::unlink(entry.path().c_str()) == 0) ++removed;
    }
  }
  return removed;
}

}  // namespace azt::linux_os
