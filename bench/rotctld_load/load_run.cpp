#include "load_run.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <utility>

namespace rotctld_load {
namespace {

using std::chrono::nanoseconds;

constexpr std::size_t kMaxReplyBytes = 1024;  // a p reply is ~20 bytes; more is a broken server
constexpr auto kReconnectDelay = std::chrono::milliseconds(100);
// Hamlib's rotctld listens with a backlog of 4 (`ss -ltn` shows Send-Q 4): 50 simultaneous
// connects overflow its accept queue and the lost handshakes cost 1-3 s SYN/SYN-ACK retransmits,
// which would show up as reply timeouts. So by default a client connects only when no other
// connection is still waiting for its first reply (which proves the server accepted it).
constexpr int kMaxHandshakesInFlight = 1;

// A valid target inside 10..20° on both axes, varying per client and request (0.1° steps).
std::string set_pos_text(const Client& c) {
  const auto az_tenths =
      static_cast<int>((c.sequence * 37U + static_cast<unsigned>(c.id) * 11U) % 101U);
  const auto el_tenths =
      static_cast<int>((c.sequence * 53U + static_cast<unsigned>(c.id) * 7U) % 101U);
  std::array<char, 64> buf{};
  const int n = std::snprintf(buf.data(), buf.size(), "P %d.%d %d.%d\n", 10 + az_tenths / 10,
                              az_tenths % 10, 10 + el_tenths / 10, el_tenths % 10);
  return std::string(buf.data(), static_cast<std::size_t>(n));
}

}  // namespace

LoadRun::LoadRun(const Options& o, const Endpoint& ep, Clock::time_point measure_from,
                 Clock::time_point end)
    : options_(o), endpoint_(ep), measure_from_(measure_from), end_(end) {
  clients_.resize(static_cast<std::size_t>(o.clients));
  for (std::size_t i = 0; i < clients_.size(); ++i) clients_[i].id = static_cast<int>(i);
}

LoadRun::~LoadRun() {
  for (Client& c : clients_) close_client(c);
}

RunStats LoadRun::run() {
  const Clock::time_point start = Clock::now();
  for (Client& c : clients_) c.deadline = start;  // connect at once
  std::vector<pollfd> fds;
  for (Clock::time_point now = start; now < end_; now = Clock::now()) {
    handle_deadlines(now);
    fds.clear();
    for (const Client& c : clients_) fds.push_back(pollfd{c.fd, events_for(c), 0});
    ::poll(fds.data(), fds.size(), poll_timeout_ms(Clock::now()));
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].fd >= 0 && fds[i].revents != 0) handle_events(clients_[i], fds[i].revents);
    }
  }
  return std::move(stats_);
}

short LoadRun::events_for(const Client& c) {
  switch (c.phase) {
    case Phase::kConnecting:
    case Phase::kSending:
      return POLLOUT;
    case Phase::kAwaitingReply:
      return POLLIN;
    case Phase::kWaitReconnect:
      break;
  }
  return 0;
}

int LoadRun::poll_timeout_ms(Clock::time_point now) const {
  Clock::time_point next = std::min(end_, now + std::chrono::milliseconds(50));
  for (const Client& c : clients_) {
    if (c.phase != Phase::kWaitReconnect || may_connect()) next = std::min(next, c.deadline);
  }
  const auto ms = std::chrono::ceil<std::chrono::milliseconds>(next - now).count();
  return static_cast<int>(std::clamp<long long>(ms, 0, 50));
}

void LoadRun::handle_deadlines(Clock::time_point now) {
  for (Client& c : clients_) {
    if (now < c.deadline) continue;
    if (c.phase == Phase::kWaitReconnect) {
      if (may_connect()) begin_connect(c, now);
    } else {  // connect, send or reply timed out
      ++(c.phase == Phase::kConnecting ? stats_.connect_timeouts : stats_.timeouts);
      fail(c, now);
    }
  }
}

void LoadRun::begin_connect(Client& c, Clock::time_point now) {
  c.fd = start_connect(endpoint_);
  if (c.fd < 0) {
    ++stats_.connect_failures;
    fail(c, now);
    return;
  }
  c.phase = Phase::kConnecting;
  set_fresh(c, true);
  c.deadline = now + std::chrono::milliseconds(options_.timeout_ms);
}

void LoadRun::handle_events(Client& c, short revents) {
  const Clock::time_point now = Clock::now();
  if (c.phase == Phase::kConnecting) {
    if (!connect_succeeded(c.fd)) {
      ++stats_.connect_failures;
      fail(c, now);
      return;
    }
    c.in.clear();
    send_next(c, now);
  } else if (c.phase == Phase::kSending) {
    flush(c, now);
  } else if (c.phase == Phase::kAwaitingReply && (revents & (POLLIN | POLLHUP | POLLERR))) {
    receive(c, now);
  }
}

void LoadRun::send_next(Client& c, Clock::time_point now) {
  c.out = c.request == Request::kGetPos ? std::string("p\n") : set_pos_text(c);
  c.out_sent = 0;
  c.sent_at = now;
  c.phase = Phase::kSending;
  c.deadline = now + std::chrono::milliseconds(options_.timeout_ms);
  flush(c, now);
}

void LoadRun::flush(Client& c, Clock::time_point now) {
  while (c.out_sent < c.out.size()) {
    const ssize_t n =
        ::send(c.fd, c.out.data() + c.out_sent, c.out.size() - c.out_sent, MSG_NOSIGNAL);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;  // POLLOUT resumes
    if (n <= 0) {
      ++stats_.disconnects;
      fail(c, now);
      return;
    }
    c.out_sent += static_cast<std::size_t>(n);
  }
  c.phase = Phase::kAwaitingReply;  // the deadline set in send_next() still holds
}

void LoadRun::receive(Client& c, Clock::time_point now) {
  std::array<char, 512> buf{};
  const ssize_t n = ::recv(c.fd, buf.data(), buf.size(), 0);
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return;
  if (n <= 0) {
    ++stats_.disconnects;
    fail(c, now);
    return;
  }
  c.in.append(buf.data(), static_cast<std::size_t>(n));
  const ReplyState state = judge_reply(c.request, c.in);
  if (state == ReplyState::kIncomplete && c.in.size() <= kMaxReplyBytes) return;
  if (state != ReplyState::kOk) {
    ++stats_.bad_replies;
    fail(c, now);  // resynchronise on a fresh connection
    return;
  }
  if (c.sent_at >= measure_from_ && now <= end_) {
    stats_.latency.add(static_cast<std::uint64_t>(nanoseconds(now - c.sent_at).count()));
  }
  c.in.clear();
  set_fresh(c, false);
  c.request = c.request == Request::kGetPos ? Request::kSetPos : Request::kGetPos;
  ++c.sequence;
  send_next(c, now);
}

void LoadRun::fail(Client& c, Clock::time_point now) {
  ++stats_.errors;
  set_fresh(c, false);
  close_client(c);
  c.phase = Phase::kWaitReconnect;
  c.deadline = now + kReconnectDelay;
}

bool LoadRun::may_connect() const {
  return options_.burst || fresh_count_ < kMaxHandshakesInFlight;
}

void LoadRun::set_fresh(Client& c, bool fresh) {
  if (c.fresh != fresh) fresh_count_ += fresh ? 1 : -1;
  c.fresh = fresh;
}

void LoadRun::close_client(Client& c) {
  if (c.fd >= 0) ::close(c.fd);
  c.fd = -1;
  c.in.clear();
}

}  // namespace rotctld_load
