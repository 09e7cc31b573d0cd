#pragma once
// The GPS receiver through gpsd (docs/gps.md): a TCP client on the daemon's Asio loop that asks
// gpsd to stream JSON (?WATCH) and decodes each report with libgps's own parser (gps_unpack), so
// the protocol stays gpsd's to define. Connecting, reading and reconnecting are all asynchronous:
// nothing here blocks the loop. When gpsd goes away (it restarts, it is not running yet) the
// client says so and tries again every retry period; a line longer than gpsd ever sends, or one
// libgps cannot parse, is dropped and counted, never trusted.

#include <functional>
#include <memory>
#include <string>

#include "azt/gnss/gps_fix.hpp"
#include "azt/linux/asio.hpp"

namespace azt::linux_os {

struct GpsdClientConfig {
  std::string host = "127.0.0.1";
  std::string port = "2947";
  double retry_s = 2.0;  ///< a restarted gpsd is found again within this (+ its start-up)
};

struct GpsdEvents {
  std::function<void()> connected;
  std::function<void(const std::string& why)> disconnected;
  std::function<void(const gnss::GpsFix&)> fix;  ///< each TPV
  std::function<void(const gnss::GpsSky&)> sky;  ///< each SKY
};

class GpsdClient {
 public:
  /// Starts connecting at once; `events` are called on the loop.
  GpsdClient(boost::asio::io_context& io, GpsdClientConfig config, GpsdEvents events);
  ~GpsdClient();
  GpsdClient(const GpsdClient&) = delete;
  GpsdClient& operator=(const GpsdClient&) = delete;
  GpsdClient(GpsdClient&&) = delete;
  GpsdClient& operator=(GpsdClient&&) = delete;

  [[nodiscard]] bool connected() const { return connected_; }
  /// Lines dropped: too long, or not a report libgps could read.
  [[nodiscard]] std::size_t rejected_lines() const { return rejected_; }
  [[nodiscard]] std::string describe() const;

 private:
  struct Impl;
  void connect();
  void read();
  void on_line(const std::string& line);
  void lost(const std::string& why);

  boost::asio::ip::tcp::resolver resolver_;
  boost::asio::ip::tcp::socket socket_;
  boost::asio::steady_timer retry_timer_;
  boost::asio::streambuf in_;
  GpsdClientConfig config_;
  GpsdEvents events_;
  std::unique_ptr<Impl> impl_;  ///< libgps's gps_data_t, kept between reports
  bool connected_ = false;
  bool down_reported_ = false;
  std::size_t rejected_ = 0;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace azt::linux_os
