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
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <vector>

#include "idle_connections.hpp"
#include "load_clock.hpp"
#include "load_run.hpp"
#include "options.hpp"
#include "report.hpp"
#include "sockets.hpp"

using namespace rotctld_load;  // this program's own parts (bench/rotctld_load/)

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
