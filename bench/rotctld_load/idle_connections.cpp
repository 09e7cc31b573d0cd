#include "idle_connections.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>

#include "load_clock.hpp"

namespace rotctld_load {
namespace {

constexpr auto kIdleConnectTimeout = std::chrono::seconds(10);  // for all idle connections
constexpr auto kIdleConnectPacing = std::chrono::milliseconds(1);

// Connects one socket, waiting until `give_up` at most; -1 when it failed.
int connect_before(const Endpoint& ep, Clock::time_point give_up) {
  const int fd = start_connect(ep);
  if (fd < 0) return -1;
  pollfd p{fd, POLLOUT, 0};
  while (Clock::now() < give_up) {
    if (::poll(&p, 1, 100) > 0) {
      if (connect_succeeded(fd)) return fd;
      break;
    }
  }
  ::close(fd);
  return -1;
}

}  // namespace

std::vector<int> open_idle(const Endpoint& ep, int count) {
  std::vector<int> fds;
  const Clock::time_point give_up = Clock::now() + kIdleConnectTimeout;
  for (int i = 0; i < count && Clock::now() < give_up; ++i) {
    const int fd = connect_before(ep, give_up);
    if (fd >= 0) fds.push_back(fd);
    const timespec pause{0, std::chrono::nanoseconds(kIdleConnectPacing).count()};
    ::nanosleep(&pause, nullptr);
  }
  return fds;
}

std::uint64_t close_idle(const std::vector<int>& fds) {
  std::uint64_t dropped = 0;
  for (int fd : fds) {
    char byte = 0;
    const ssize_t n = ::recv(fd, &byte, 1, MSG_DONTWAIT | MSG_PEEK);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)) ++dropped;
    ::close(fd);
  }
  return dropped;
}

}  // namespace rotctld_load
