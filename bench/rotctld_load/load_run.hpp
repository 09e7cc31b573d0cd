#pragma once
// rotctld_load's closed-loop clients: C connections alternating `p` and `P az el`, each waiting for
// the whole reply before the next request, on one thread with poll(); a client that errs counts
// it, closes and reconnects after a pause.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "latency_histogram.hpp"
#include "load_clock.hpp"
#include "options.hpp"
#include "rotctld_reply.hpp"
#include "sockets.hpp"

namespace rotctld_load {

enum class Phase { kWaitReconnect, kConnecting, kSending, kAwaitingReply };

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

class LoadRun {
 public:
  LoadRun(const Options& o, const Endpoint& ep, Clock::time_point measure_from,
          Clock::time_point end);
  ~LoadRun();
  LoadRun(const LoadRun&) = delete;
  LoadRun& operator=(const LoadRun&) = delete;
  RunStats run();

 private:
  static short events_for(const Client& c);
  // Waits until the nearest client deadline, at most 50 ms and never past the end of the run.
  int poll_timeout_ms(Clock::time_point now) const;
  void handle_deadlines(Clock::time_point now);
  void begin_connect(Client& c, Clock::time_point now);
  void handle_events(Client& c, short revents);
  void send_next(Client& c, Clock::time_point now);
  void flush(Client& c, Clock::time_point now);
  void receive(Client& c, Clock::time_point now);
  // Counts one error, closes the connection and reconnects after a short pause.
  void fail(Client& c, Clock::time_point now);
  bool may_connect() const;
  void set_fresh(Client& c, bool fresh);
  static void close_client(Client& c);
  const Options& options_;
  const Endpoint& endpoint_;
  Clock::time_point measure_from_;
  Clock::time_point end_;
  std::vector<Client> clients_;
  RunStats stats_;
  int fresh_count_ = 0;
};

}  // namespace rotctld_load
