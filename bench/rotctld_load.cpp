// Load generator for a rotctld-protocol (Hamlib "rotctld") TCP server: C closed-loop clients
// alternate `p` (get position, reply "az\nel\n") and `P az el` (set position, reply "RPRT 0\n"),
// each waiting for the whole reply before the next request. Prints one Markdown table row (or one
// JSON object with --json): label, clients, requests/s, p50/p99/max latency in µs, errors.
// Not a test: bench/rotctld_compare.sh runs it against Debian's `rotctld -m 1` and azeltrack.
//
// Run: rotctld_load --host 127.0.0.1 --port 4533 --clients 50 --seconds 5 [--warmup 1]
//                   [--label NAME] [--idle K] [--timeout-ms 2000] [--json] [--header]
//
// Latencies are recorded only for requests sent after the warm-up and answered before the end;
// requests/s counts those. Errors count the whole run (warm-up included): an RPRT other than 0,
// a reply that is not two numbers, a disconnect, a refused connect, a reply timeout (the client
// then reconnects), and idle connections the server closed. Latency uses a log-linear histogram
// (1024 exact ns buckets, then 512 per octave: < 0.2 % error), so memory is bounded however long
// the run; the max is exact.
// Single-threaded (poll()) so the generator takes at most one core of a small machine.
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::nanoseconds;

constexpr int kMaxClients = 4096;
constexpr int kMaxIdle = 16384;
constexpr double kMaxSeconds = 3600.0;
constexpr std::size_t kMaxReplyBytes = 1024;  // a p reply is ~20 bytes; more is a broken server
constexpr auto kReconnectDelay = std::chrono::milliseconds(100);
constexpr auto kIdleConnectTimeout = std::chrono::seconds(10);  // for all idle connections
constexpr auto kIdleConnectPacing = std::chrono::milliseconds(1);
// Hamlib's rotctld listens with a backlog of 4 (`ss -ltn` shows Send-Q 4): 50 simultaneous
// connects overflow its accept queue and the lost handshakes cost 1-3 s SYN/SYN-ACK retransmits,
// which would show up as reply timeouts. So by default a client connects only when no other
// connection is still waiting for its first reply (which proves the server accepted it).
constexpr int kMaxHandshakesInFlight = 1;

// ---------------------------------------------------------------------------------------------
// Options

struct Options {
  std::string host = "127.0.0.1";
  std::string port;
  int clients = 1;
  double seconds = 5.0;
  double warmup_s = 1.0;
  std::string label = "server";
  int idle = 0;
  int timeout_ms = 2000;
  bool json = false;
  bool header = false;
  bool burst = false;  // open every connection at once instead of one handshake at a time
};

void print_usage(FILE* out) {
  std::fprintf(out,
               "usage: rotctld_load --port N [--host 127.0.0.1] [--clients C] [--seconds S]\n"
               "                    [--warmup 1] [--label NAME] [--idle K] [--timeout-ms 2000]\n"
               "                    [--json] [--header] [--burst]\n");
}

bool parse_int(std::string_view text, int lo, int hi, int& out) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || value < lo || value > hi) {
    return false;
  }
  out = value;
  return true;
}

bool parse_seconds(std::string_view text, double lo, double& out) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value) ||
      value < lo || value > kMaxSeconds) {
    return false;
  }
  out = value;
  return true;
}

// Applies one "--name value" pair; false when the name is unknown or the value out of range.
bool apply_option(Options& o, std::string_view name, std::string_view value) {
  int port = 0;
  if (name == "--host") {
    o.host = value;
  } else if (name == "--port") {
    if (!parse_int(value, 1, 65535, port)) return false;
    o.port = value;
  } else if (name == "--label") {
    o.label = value;
    std::replace(o.label.begin(), o.label.end(), '|', '/');  // keep the Markdown row parseable
  } else if (name == "--clients") {
    return parse_int(value, 0, kMaxClients, o.clients);
  } else if (name == "--idle") {
    return parse_int(value, 0, kMaxIdle, o.idle);
  } else if (name == "--timeout-ms") {
    return parse_int(value, 10, 600000, o.timeout_ms);
  } else if (name == "--seconds") {
    return parse_seconds(value, 0.1, o.seconds);
  } else if (name == "--warmup") {
    return parse_seconds(value, 0.0, o.warmup_s);
  } else {
    return false;
  }
  return true;
}

std::optional<Options> parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--json") {
      o.json = true;
    } else if (arg == "--header") {
      o.header = true;
    } else if (arg == "--burst") {
      o.burst = true;
    } else if (arg == "--help" || arg == "-h") {
      print_usage(stdout);
      std::exit(0);
    } else if (i + 1 >= argc || !apply_option(o, arg, argv[i + 1])) {
      std::fprintf(stderr, "rotctld_load: bad or incomplete option '%s'\n", argv[i]);
      return std::nullopt;
    } else {
      ++i;
    }
  }
  if (o.port.empty()) {
    std::fprintf(stderr, "rotctld_load: --port is required\n");
    return std::nullopt;
  }
  return o;
}

// ---------------------------------------------------------------------------------------------
// Latency histogram: values below 1024 ns have their own bucket; above, each octave [2^k, 2^k+1)
// is split into 512 buckets, so a bucket is at most 1/512 of its value wide.

class LatencyHistogram {
 public:
  void add(std::uint64_t ns) {
    ns = std::min(ns, kMaxValueNs);
    ++counts_[index_of(ns)];
    ++count_;
    max_ns_ = std::max(max_ns_, ns);
  }
  std::uint64_t count() const { return count_; }
  std::uint64_t max_ns() const { return max_ns_; }
  // The q-quantile (0 < q <= 1), as the middle of its bucket; 0 with no samples.
  double quantile_ns(double q) const {
    if (count_ == 0) return 0.0;
    const auto rank = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_)));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < counts_.size(); ++i) {
      seen += counts_[i];
      if (seen >= std::max<std::uint64_t>(rank, 1)) return bucket_middle_ns(i);
    }
    return static_cast<double>(max_ns_);
  }

 private:
  static constexpr std::uint64_t kExact = 1024;
  static constexpr std::uint64_t kHalf = kExact / 2;
  static constexpr std::uint64_t kMaxValueNs = (std::uint64_t{1} << 40) - 1;  // ~18 min
  static constexpr std::size_t kBuckets = kExact + 30 * kHalf;

  static std::size_t index_of(std::uint64_t ns) {
    if (ns < kExact) return static_cast<std::size_t>(ns);
    const auto shift = static_cast<unsigned>(std::bit_width(ns)) - 10U;  // >= 1
    return static_cast<std::size_t>(kExact + (shift - 1U) * kHalf + ((ns >> shift) - kHalf));
  }
  static double bucket_middle_ns(std::size_t index) {
    if (index < kExact) return static_cast<double>(index);
    const std::uint64_t k = index - kExact;
    const std::uint64_t shift = k / kHalf + 1U;
    const std::uint64_t low = (k % kHalf + kHalf) << shift;
    return static_cast<double>(low) + static_cast<double>((std::uint64_t{1} << shift) - 1U) / 2.0;
  }

  std::array<std::uint64_t, kBuckets> counts_{};
  std::uint64_t count_ = 0;
  std::uint64_t max_ns_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Sockets

struct Endpoint {
  sockaddr_storage addr{};
  socklen_t len = 0;
};

std::optional<Endpoint> resolve(const Options& o) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* list = nullptr;
  const int rc = getaddrinfo(o.host.c_str(), o.port.c_str(), &hints, &list);
  if (rc != 0 || list == nullptr) {
    std::fprintf(stderr, "rotctld_load: cannot resolve %s: %s\n", o.host.c_str(), gai_strerror(rc));
    return std::nullopt;
  }
  Endpoint ep;
  std::memcpy(&ep.addr, list->ai_addr, list->ai_addrlen);
  ep.len = list->ai_addrlen;
  freeaddrinfo(list);
  return ep;
}

// Starts a non-blocking connect with TCP_NODELAY (requests are a few bytes: Nagle plus delayed
// ACK would otherwise add tens of ms). Returns the fd, or -1 when the connect failed at once.
int start_connect(const Endpoint& ep) {
  const int fd = ::socket(ep.addr.ss_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&ep.addr), ep.len) == 0 ||
      errno == EINPROGRESS) {
    return fd;
  }
  ::close(fd);
  return -1;
}

bool connect_succeeded(int fd) {
  int err = 0;
  socklen_t len = sizeof err;
  return ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len) == 0 && err == 0;
}

// Raises the soft descriptor limit toward the hard one when C + K sockets need it.
void ensure_fd_limit(int sockets) {
  rlimit lim{};
  if (::getrlimit(RLIMIT_NOFILE, &lim) != 0) return;
  const auto want = static_cast<rlim_t>(sockets + 64);
  if (lim.rlim_cur >= want) return;
  lim.rlim_cur = std::min(want, lim.rlim_max);
  ::setrlimit(RLIMIT_NOFILE, &lim);
}

// ---------------------------------------------------------------------------------------------
// Closed-loop clients

enum class Phase { kWaitReconnect, kConnecting, kSending, kAwaitingReply };
enum class Request { kGetPos, kSetPos };

struct Client {
  int id = 0;
  int fd = -1;
  Phase phase = Phase::kWaitReconnect;
  bool fresh = false;  // connected, first reply not yet received
  Request request = Request::kGetPos;
  std::uint64_t sequence = 0;
  std::string out;  // the request being sent
  std::size_t out_sent = 0;
  std::string in;  // reply bytes received so far (bounded by kMaxReplyBytes)
  Clock::time_point sent_at{};
  Clock::time_point deadline{};  // reconnect time, connect or reply timeout
};

struct RunStats {
  LatencyHistogram latency;
  std::uint64_t errors = 0;
  std::uint64_t timeouts = 0;  // no (complete) reply within --timeout-ms
  std::uint64_t connect_timeouts = 0;
  std::uint64_t disconnects = 0;
  std::uint64_t bad_replies = 0;
  std::uint64_t connect_failures = 0;
};

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

bool is_number(std::string_view line) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), value);
  return ec == std::errc{} && end == line.data() + line.size() && std::isfinite(value);
}

enum class ReplyState { kIncomplete, kOk, kError };

// Judges the reply bytes so far: `p` wants two numeric lines unless the first is an RPRT line;
// `P` wants one "RPRT 0" line. Extra bytes after a complete reply are a protocol error.
ReplyState judge_reply(Request request, std::string_view in) {
  const std::size_t first_end = in.find('\n');
  if (first_end == std::string_view::npos) return ReplyState::kIncomplete;
  const std::string_view first = in.substr(0, first_end);
  if (first.starts_with("RPRT")) {
    const bool ok = request == Request::kSetPos && first == "RPRT 0";
    return ok && in.size() == first_end + 1 ? ReplyState::kOk : ReplyState::kError;
  }
  if (request == Request::kSetPos) return ReplyState::kError;
  const std::size_t second_end = in.find('\n', first_end + 1);
  if (second_end == std::string_view::npos) return ReplyState::kIncomplete;
  const std::string_view second = in.substr(first_end + 1, second_end - first_end - 1);
  const bool ok = is_number(first) && is_number(second) && in.size() == second_end + 1;
  return ok ? ReplyState::kOk : ReplyState::kError;
}

class LoadRun {
 public:
  LoadRun(const Options& o, const Endpoint& ep, Clock::time_point measure_from,
          Clock::time_point end)
      : options_(o), endpoint_(ep), measure_from_(measure_from), end_(end) {
    clients_.resize(static_cast<std::size_t>(o.clients));
    for (std::size_t i = 0; i < clients_.size(); ++i) clients_[i].id = static_cast<int>(i);
  }
  ~LoadRun() {
    for (Client& c : clients_) close_client(c);
  }
  LoadRun(const LoadRun&) = delete;
  LoadRun& operator=(const LoadRun&) = delete;

  RunStats run() {
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

 private:
  static short events_for(const Client& c) {
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

  // Waits until the nearest client deadline, at most 50 ms and never past the end of the run.
  int poll_timeout_ms(Clock::time_point now) const {
    Clock::time_point next = std::min(end_, now + std::chrono::milliseconds(50));
    for (const Client& c : clients_) {
      if (c.phase != Phase::kWaitReconnect || may_connect()) next = std::min(next, c.deadline);
    }
    const auto ms = std::chrono::ceil<std::chrono::milliseconds>(next - now).count();
    return static_cast<int>(std::clamp<long long>(ms, 0, 50));
  }

  void handle_deadlines(Clock::time_point now) {
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

  void begin_connect(Client& c, Clock::time_point now) {
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

  void handle_events(Client& c, short revents) {
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

  void send_next(Client& c, Clock::time_point now) {
    c.out = c.request == Request::kGetPos ? std::string("p\n") : set_pos_text(c);
    c.out_sent = 0;
    c.sent_at = now;
    c.phase = Phase::kSending;
    c.deadline = now + std::chrono::milliseconds(options_.timeout_ms);
    flush(c, now);
  }

  void flush(Client& c, Clock::time_point now) {
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

  void receive(Client& c, Clock::time_point now) {
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

  // Counts one error, closes the connection and reconnects after a short pause.
  void fail(Client& c, Clock::time_point now) {
    ++stats_.errors;
    set_fresh(c, false);
    close_client(c);
    c.phase = Phase::kWaitReconnect;
    c.deadline = now + kReconnectDelay;
  }

  bool may_connect() const { return options_.burst || fresh_count_ < kMaxHandshakesInFlight; }

  void set_fresh(Client& c, bool fresh) {
    if (c.fresh != fresh) fresh_count_ += fresh ? 1 : -1;
    c.fresh = fresh;
  }

  static void close_client(Client& c) {
    if (c.fd >= 0) ::close(c.fd);
    c.fd = -1;
    c.in.clear();
  }

  const Options& options_;
  const Endpoint& endpoint_;
  Clock::time_point measure_from_;
  Clock::time_point end_;
  std::vector<Client> clients_;
  RunStats stats_;
  int fresh_count_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Idle connections: opened before the run, held silent throughout, checked at the end.

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

// Opens the idle connections one at a time, paced (see kMaxHandshakesInFlight: an idle client
// never gets a reply, so pacing is the only gentle way to keep a small accept queue from
// overflowing).
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

// Closes the idle sockets; returns how many the server had closed (EOF or error) meanwhile.
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

// ---------------------------------------------------------------------------------------------
// Report

struct Summary {
  std::string label;
  int clients = 0;
  int idle = 0;
  double measured_s = 0.0;
  std::uint64_t requests = 0;
  double rps = 0.0;
  double p50_us = 0.0;
  double p99_us = 0.0;
  double max_us = 0.0;
  std::uint64_t errors = 0;
};

std::string json_escape(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      out += ' ';
    } else {
      out += ch;
    }
  }
  return out;
}

void print_summary(const Summary& s, const Options& o) {
  if (o.json) {
    std::printf(
        "{\"label\":\"%s\",\"clients\":%d,\"idle\":%d,\"seconds\":%.3f,\"requests\":%llu,"
        "\"rps\":%.1f,\"p50_us\":%.1f,\"p99_us\":%.1f,\"max_us\":%.1f,\"errors\":%llu}\n",
        json_escape(s.label).c_str(), s.clients, s.idle, s.measured_s,
        static_cast<unsigned long long>(s.requests), s.rps, s.p50_us, s.p99_us, s.max_us,
        static_cast<unsigned long long>(s.errors));
    return;
  }
  if (o.header) {
    std::printf("| server | clients | req/s | p50 µs | p99 µs | max µs | errors |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  }
  std::printf("| %s | %d | %.0f | %.1f | %.1f | %.1f | %llu |\n", s.label.c_str(), s.clients, s.rps,
              s.p50_us, s.p99_us, s.max_us, static_cast<unsigned long long>(s.errors));
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<Options> options = parse_options(argc, argv);
  if (!options) {
    print_usage(stderr);
    return 2;
  }
  const Options& o = *options;
  const std::optional<Endpoint> endpoint = resolve(o);
  if (!endpoint) return 2;
  ensure_fd_limit(o.clients + o.idle);

  const std::vector<int> idle = open_idle(*endpoint, o.idle);
  if (o.idle > 0) {
    std::fprintf(stderr, "rotctld_load: %zu of %d idle connections open\n", idle.size(), o.idle);
  }
  const Clock::time_point start = Clock::now();
  const auto to_duration = [](double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  };
  const Clock::time_point measure_from = start + to_duration(o.warmup_s);
  const Clock::time_point end = measure_from + to_duration(o.seconds);
  LoadRun run(o, *endpoint, measure_from, end);
  const RunStats stats = run.run();
  const std::uint64_t idle_errors =
      static_cast<std::uint64_t>(o.idle) - idle.size() + close_idle(idle);

  Summary s;
  s.label = o.label;
  s.clients = o.clients;
  s.idle = o.idle;
  s.measured_s = std::chrono::duration<double>(end - measure_from).count();
  s.requests = stats.latency.count();
  s.rps = static_cast<double>(s.requests) / s.measured_s;
  s.p50_us = stats.latency.quantile_ns(0.50) / 1000.0;
  s.p99_us = stats.latency.quantile_ns(0.99) / 1000.0;
  s.max_us = static_cast<double>(stats.latency.max_ns()) / 1000.0;
  s.errors = stats.errors + idle_errors;
  if (s.errors > 0) {
    std::fprintf(stderr,
                 "rotctld_load: %s: %llu errors (%llu timeouts, %llu disconnects, %llu bad "
                 "replies, %llu failed and %llu timed-out connects, %llu idle lost)\n",
                 o.label.c_str(), static_cast<unsigned long long>(s.errors),
                 static_cast<unsigned long long>(stats.timeouts),
                 static_cast<unsigned long long>(stats.disconnects),
                 static_cast<unsigned long long>(stats.bad_replies),
                 static_cast<unsigned long long>(stats.connect_failures),
                 static_cast<unsigned long long>(stats.connect_timeouts),
                 static_cast<unsigned long long>(idle_errors));
  }
  print_summary(s, o);
  return 0;
}
