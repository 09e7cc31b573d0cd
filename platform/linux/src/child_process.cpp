#include "azt/linux/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/eventfd.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <limits>

namespace azt::linux_os {
namespace {

using Clock = std::chrono::steady_clock;

/// A descriptor readable once `pid` has ended (Linux 5.3), or -1. Called through syscall():
/// Debian 12's <sys/pidfd.h> declares the wrapper without C linkage.
int open_pidfd(pid_t pid) { return static_cast<int>(::syscall(SYS_pidfd_open, pid, 0)); }

Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

std::vector<char*> c_strings(const std::vector<std::string>& strings) {
  std::vector<char*> out;
  out.reserve(strings.size() + 1);
  for (const auto& s : strings) out.push_back(const_cast<char*>(s.c_str()));  // NOLINT: POSIX API
  out.push_back(nullptr);
  return out;
}

/// The child starts clean whatever the daemon's thread had: default signal dispositions (an
/// ignored SIGPIPE would otherwise be inherited), nothing blocked, a process group of its own.
struct SpawnAttributes {
  posix_spawnattr_t attr{};
  posix_spawn_file_actions_t actions{};

  explicit SpawnAttributes(int out_fd) {
    posix_spawnattr_init(&attr);
    sigset_t all;
    sigset_t none;
    sigfillset(&all);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attr, &all);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setpgroup(&attr, 0);
    posix_spawnattr_setflags(
        &attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETPGROUP);
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out_fd, 1);
    posix_spawn_file_actions_adddup2(&actions, out_fd, 2);
    // The daemon's sockets and devices are not all close-on-exec (Asio's are not): none of them
    // reaches the hook, which could otherwise hold a listening port past the daemon's restart.
    posix_spawn_file_actions_addclosefrom_np(&actions, 3);
  }
  ~SpawnAttributes() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
  }
  SpawnAttributes(const SpawnAttributes&) = delete;
  SpawnAttributes& operator=(const SpawnAttributes&) = delete;
};

/// The program's pid, or 0 with `error` set.
pid_t spawn(const ChildSpec& spec, int out_fd, std::string& error) {
  const SpawnAttributes how(out_fd);
  auto argv = c_strings(spec.argv);
  auto envp = c_strings(spec.env);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, argv[0], &how.actions, &how.attr, argv.data(), envp.data());
  if (rc != 0) {
    error = spec.argv[0] + ": " + std::strerror(rc);
    return 0;
  }
  return pid;
}

/// The output's first lines, then only a count of what follows.
class OutputKeeper {
 public:
  OutputKeeper(std::size_t max_lines, std::size_t max_bytes)
      : max_lines_(max_lines), max_bytes_(max_bytes) {}

  void add(const char* data, std::size_t n, ChildResult& into) {
    std::size_t i = 0;
    for (; i < n && !full(into); ++i) {
      into.first_lines.push_back(data[i]);
      if (data[i] == '\n') ++lines_;
    }
    into.dropped_bytes += n - i;
  }

 private:
  [[nodiscard]] bool full(const ChildResult& r) const {
    return lines_ >= max_lines_ || r.first_lines.size() >= max_bytes_;
  }
  std::size_t max_lines_;
  std::size_t max_bytes_;
  std::size_t lines_ = 0;
};

/// The wait for one running program: its output, its deadlines, a stop, its end.
class ChildWatch {
 public:
  ChildWatch(const ChildSpec& spec, pid_t pid, UniqueFd out, const ChildStop* stop)
      : spec_(spec),
        pid_(pid),
        pidfd_(open_pidfd(pid)),
        out_(std::move(out)),
        stop_(stop),
        keeper_(spec.max_lines, spec.max_bytes),
        term_at_(Clock::now() + seconds(spec.timeout_s)) {}

  void run(ChildResult& r) {
    while (!reap(r)) step(r);
    drain_left(r);
    if (r.timed_out && !kill_sent_) finish_group(r);
  }

 private:
  void step(ChildResult& r) {
    enforce_deadlines(r);
    std::array<pollfd, 3> fds{{{out_.get(), POLLIN, 0},
                               {pidfd_.get(), POLLIN, 0},
                               {stop_ != nullptr ? stop_->fd() : -1, POLLIN, 0}}};
    if (::poll(fds.data(), fds.size(), poll_ms()) <= 0) return;
    if (fds[0].revents != 0 && at_end(read_some(r))) out_.reset();
    if (fds[2].revents != 0) kill_now(r);
  }

  void enforce_deadlines(ChildResult& r) {
    const auto now = Clock::now();
    if (!term_sent_ && now >= term_at_) {
      ::kill(-pid_, SIGTERM);
      r.timed_out = true;
      term_sent_ = true;
      kill_at_ = now + seconds(spec_.kill_after_s);
    }
    if (term_sent_ && !kill_sent_ && now >= kill_at_) {
      ::kill(-pid_, SIGKILL);
      kill_sent_ = true;
    }
  }

  void kill_now(ChildResult& r) {
    if (!kill_sent_) ::kill(-pid_, SIGKILL);
    kill_sent_ = true;
    r.stopped = true;
  }

  /// Until the next deadline; in slices when the kernel gives no pidfd to wake on the end.
  [[nodiscard]] int poll_ms() const {
    const auto next = !term_sent_ ? term_at_ : (!kill_sent_ ? kill_at_ : Clock::time_point::max());
    const auto left = next == Clock::time_point::max()
                          ? std::chrono::milliseconds(std::numeric_limits<int>::max())
                          : std::chrono::ceil<std::chrono::milliseconds>(next - Clock::now());
    const std::int64_t cap = pidfd_.valid() ? std::numeric_limits<int>::max() : 50;
    return static_cast<int>(std::clamp<std::int64_t>(left.count(), 0, cap));
  }

  /// One read of the output: what read() returned.
  ssize_t read_some(ChildResult& r) {
    std::array<char, 4096> buffer{};
    const ssize_t n = ::read(out_.get(), buffer.data(), buffer.size());
    if (n > 0) keeper_.add(buffer.data(), static_cast<std::size_t>(n), r);
    return n;
  }

  /// The output has ended (or the pipe broke): not "nothing yet".
  static bool at_end(ssize_t n) { return n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN); }

  /// What the program wrote just before it ended; bounded, since what it left running in the
  /// background may hold the pipe and keep writing.
  void drain_left(ChildResult& r) {
    for (int reads = 0; out_.valid() && reads < 16; ++reads) {
      if (read_some(r) <= 0) break;
    }
    out_.reset();
  }

  bool reap(ChildResult& r) {
    int status = 0;
    const pid_t got = ::waitpid(pid_, &status, WNOHANG);
    if (got == 0 || (got < 0 && errno == EINTR)) return false;
    if (got == pid_ && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (got == pid_ && WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    return true;  // ECHILD: reaped by someone else (SIGCHLD ignored); its status is unknown
  }

  /// After a timeout the program is gone; what it started has until SIGKILL to follow it.
  void finish_group(ChildResult& r) {
    while (::kill(-pid_, 0) == 0 && Clock::now() < kill_at_) {
      pollfd stop{stop_ != nullptr ? stop_->fd() : -1, POLLIN, 0};
      if (::poll(&stop, 1, 20) > 0) {
        r.stopped = true;
        break;
      }
    }
    // Only a group that still has members: its number is free for reuse once it is empty.
    if (::kill(-pid_, 0) == 0) ::kill(-pid_, SIGKILL);
    kill_sent_ = true;
  }

  const ChildSpec& spec_;
  pid_t pid_;
  UniqueFd pidfd_;  ///< readable when the program has ended; invalid before Linux 5.3
  UniqueFd out_;
  const ChildStop* stop_;
  OutputKeeper keeper_;
  Clock::time_point term_at_;
  Clock::time_point kill_at_ = Clock::time_point::max();
  bool term_sent_ = false;
  bool kill_sent_ = false;
};

}  // namespace

ChildStop::ChildStop() : fd_(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {}

void ChildStop::stop() const {
  const std::uint64_t one = 1;
  [[maybe_unused]] const ssize_t n = ::write(fd_.get(), &one, sizeof one);
}

ChildResult run_child(const ChildSpec& spec, const ChildStop* stop) {
  ChildResult r;
  if (spec.argv.empty() || spec.argv[0].empty()) {
    r.spawn_error = "no program to run";
    return r;
  }
  std::array<int, 2> fds{};
  if (::pipe2(fds.data(), O_CLOEXEC) != 0) {
    r.spawn_error = std::string("pipe: ") + std::strerror(errno);
    return r;
  }
  UniqueFd read_end(fds[0]);
  UniqueFd write_end(fds[1]);
  const auto start = Clock::now();
  r.pid = spawn(spec, write_end.get(), r.spawn_error);
  write_end.reset();  // only the program writes now: the end of its output is seen
  if (r.pid == 0) return r;
  ::fcntl(read_end.get(), F_SETFL, O_NONBLOCK);
  ChildWatch(spec, r.pid, std::move(read_end), stop).run(r);
  r.duration_s = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

}  // namespace azt::linux_os
