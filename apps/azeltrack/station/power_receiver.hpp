#pragma once
// The receiver whose power the pointing scans read (issue 16 §3, [receiver]): rtl_power's CSV
// lines from a FIFO or file (linux_os::LineFeed) or dB lines in UDP datagrams, each reading or
// malformed line handed to the core's PowerFeed, which counts good, malformed and missing
// readings. Everything on the daemon's loop; nothing waits for the receiver.

#include <functional>
#include <memory>
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
};

}  // namespace azt::app
