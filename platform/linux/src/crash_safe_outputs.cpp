#include "azt/linux/crash_safe_outputs.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <mutex>

namespace azt::linux_os {
namespace {

struct CrashWrite {
  std::array<char, 256> path{};
  std::array<char, 16> text{};
  std::size_t text_size = 0;
  std::atomic<bool> used{false};
};

// Fixed storage: the handler may not allocate, and must see only complete entries (`used` is
// set last, with release order).
std::array<CrashWrite, 32> g_writes;
std::mutex g_register;  // registrations only; the handler never takes it
std::atomic<bool> g_installed{false};

constexpr std::array<int, 5> kFatalSignals = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT};

int replay() {
  int done = 0;
  for (auto& w : g_writes) {
    if (!w.used.load(std::memory_order_acquire)) continue;
    const int fd = ::open(w.path.data(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) continue;
    if (::write(fd, w.text.data(), w.text_size) == static_cast<ssize_t>(w.text_size)) ++done;
    ::close(fd);
  }
  return done;
}

void on_fatal_signal(int signal) {
  replay();
  // Default action from here on, then the same signal again: the process dies as it would have.
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

}  // namespace

bool register_crash_write(const std::string& path, std::string_view text) {
  if (path.size() >= CrashWrite{}.path.size() || text.size() >= CrashWrite{}.text.size()) {
    return false;
  }
  const std::lock_guard lock(g_register);
  for (auto& w : g_writes) {
    if (w.used.load(std::memory_order_relaxed) && path == w.path.data() &&
        text == std::string_view(w.text.data(), w.text_size)) {
      return true;  // already kept (a channel opened again)
    }
  }
  for (auto& w : g_writes) {
    if (w.used.load(std::memory_order_relaxed)) continue;
    std::memcpy(w.path.data(), path.c_str(), path.size() + 1);
    std::memcpy(w.text.data(), text.data(), text.size());
    w.text_size = text.size();
    w.used.store(true, std::memory_order_release);
    return true;
  }
  return false;
}

void forget_crash_writes(const std::string& path) {
  const std::lock_guard lock(g_register);
  for (auto& w : g_writes) {
    if (w.used.load(std::memory_order_relaxed) && path == w.path.data()) {
      w.used.store(false, std::memory_order_release);
    }
  }
}

void install_crash_handlers() {
  if (g_installed.exchange(true)) return;
  for (const int signal : kFatalSignals) {
    struct sigaction action {};
    action.sa_handler = on_fatal_signal;
    sigemptyset(&action.sa_mask);
    // A crash inside the handler ends the process at once.
    action.sa_flags = static_cast<int>(SA_RESETHAND);
    ::sigaction(signal, &action, nullptr);
  }
}

int run_crash_writes() { return replay(); }

}  // namespace azt::linux_os
