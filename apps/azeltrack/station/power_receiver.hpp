#pragma once
// The receiver whose power the pointing scans read (docs/calibration.md, [receiver]): rtl_power's
// CSV lines from a FIFO or file (linux_os::LineFeed) or dB lines in UDP datagrams, each reading or
// malformed line handed to the core's PowerFeed, which counts good, malformed and missing
// readings; or, with `sim`, the simulated receiver read at its rate on the control tick.
// Everything on the daemon's loop; nothing waits for the receiver.

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "azt/calibration/power_feed.hpp"
#include "azt/linux/asio.hpp"
#include "azt/linux/line_feed.hpp"
#include "azt/linux/udp_datagram_server.hpp"
#include "config/receiver_config.hpp"

namespace azt::app {

class PowerReceiver {
 public:
  /// Opens the source; throws UsageError when a UDP port cannot be had (a FIFO or file that is
  /// not there yet is waited for and reported, not fatal).
  PowerReceiver(boost::asio::io_context& io, const ReceiverConfig& config,
                std::function<double()> monotonic_s, std::function<void(const std::string&)> log);

  /// The console's `receiver`: source, state ("off", "receiving", "silent"), power_db and its
  /// age, the counts of good, malformed and missing readings, the last malformed reason, the
  /// source's problem.
  [[nodiscard]] nlohmann::json to_json() const;
  [[nodiscard]] const calibration::PowerFeed& feed() const { return feed_; }

  /// `[receiver] source = "sim"`: `read` gives a reading now (nullopt: none to be had), taken
  /// `rate_hz` times a second by tick().
  void simulate(std::function<std::optional<double>()> read, double rate_hz);
  /// The control tick: the simulated receiver's readings due by `now_s` (monotonic).
  void tick(double now_s);

 private:
  void rtl_power_line(std::string_view line);
  void datagram(std::string_view datagram);

  ReceiverConfig config_;
  std::function<double()> now_s_;
  std::function<void(const std::string&)> log_;
  calibration::PowerFeed feed_;
  std::string problem_;
  std::unique_ptr<linux_os::LineFeed> lines_;
  std::unique_ptr<linux_os::UdpDatagramServer> udp_;
  std::function<std::optional<double>()> simulated_;
  double period_s_ = 0.2;
  double next_s_ = 0.0;
};

}  // namespace azt::app
