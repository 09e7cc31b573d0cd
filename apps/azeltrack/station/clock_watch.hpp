#pragma once
// The station's clock, watched (docs/time.md): every [time] poll_s a look at chrony, the kernel
// and the RTC runs off the loop (chronyc may take seconds), and the core's assess_clock judges
// it. The console shows the verdict as `time` and a banner when the clock cannot be trusted;
// tracking carries on either way. With [time] manage_chrony the console's NTP servers are
// written to chrony's sources file and chronyd is asked to reload them.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/linux/asio.hpp"
#include "azt/timekeeping/clock_status.hpp"
#include "azt/util/result.hpp"
#include "common/off_loop.hpp"
#include "common/periodic_look.hpp"
#include "config/time_config.hpp"

namespace azt::app {

struct ClockWatchParts {
  TimeConfig config;
  std::function<double()> monotonic_s;
  Offload offload;  ///< where the probes and the writes run (a worker thread of their own)
  /// One look at the clock, on the worker (linux_os::probe_clock in the daemon).
  std::function<timekeeping::ClockReading()> probe;
  /// The managed servers written to the sources file and reloaded by chronyd, on the worker.
  std::function<Result<bool>(const std::vector<std::string>&)> apply_servers;
  /// The servers in the managed sources file now (none: no file), on the worker.
  std::function<std::vector<std::string>()> read_servers;
  std::function<void(const std::string&)> log;
};

class ClockWatch {
 public:
  /// Checks at once, then every poll_s.
  ClockWatch(boost::asio::io_context& io, ClockWatchParts parts);

  /// The console's `time`: synced, reason, stratum, ref, offset_s, root_dispersion_s, rtc,
  /// sources, the managed servers (docs/web-api.md).
  [[nodiscard]] nlohmann::json to_json() const;
  /// Asks for a look now (a check already under way is enough).
  void check_now();
  /// The console's NTP servers. Refused (done with the error) unless [time] manage_chrony; the
  /// names are checked, written and reloaded off the loop; `done` runs on the loop.
  void set_servers(const std::vector<std::string>& servers, std::function<void(Result<bool>)> done);

 private:
  /// What one look brings back: the clock, and the managed servers.
  struct Look {
    timekeeping::ClockReading reading;
    std::vector<std::string> servers;  ///< in the managed sources file
  };
  void on_look(Look look);
  [[nodiscard]] double stale_after_s() const;

  ClockWatchParts p_;
  PeriodicLook<Look> looks_;
  std::optional<timekeeping::ClockReading> latest_;
  std::vector<std::string> servers_;          ///< in the managed sources file at the last look
  std::optional<std::string> logged_reason_;  ///< the verdict last logged ("" synced)
};

}  // namespace azt::app
