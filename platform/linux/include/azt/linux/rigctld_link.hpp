#pragma once
// One rig through Hamlib's rigctld (docs/radio.md): a TCP client on the daemon's Asio loop that
// carries the core's RigctlSession (azt/radio/rigctl_session.hpp) over the wire, modelled on the
// gpsd client: resolving, connecting, reading and writing are all asynchronous, so nothing here
// delays the control tick. When the link fails (refused, closed, a late or garbled reply) the
// socket is closed and the client tries again after a back-off that doubles from retry_s up to
// max_retry_s; the loss is reported once and the return once (the `link` callback), never every
// retry.
//
// This client never keys the transmitter: the session has no PTT command.

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "azt/linux/asio.hpp"
#include "azt/linux/rig_connection.hpp"
#include "azt/radio/rigctl_session.hpp"

namespace azt::linux_os {

struct RigctldLinkConfig {
  std::string host = "127.0.0.1";
  std::string port = "4532";  ///< rigctld's default (rigctld.1, -t)
  double retry_s = 0.5;       ///< the first retry; a restarted rigctld is found within 1 s
  double max_retry_s = 4.0;   ///< back-off cap: a down rigctld costs one connect every 4 s
  double poll_s = 0.1;        ///< how often the session's reply timeout is checked
  radio::RigctlOptions session;
};

class RigctldLink final : public RigConnection {
 public:
  /// Starts connecting at once; events arrive on the loop. `now_s`: a monotonic clock.
  RigctldLink(boost::asio::io_context& io, RigctldLinkConfig config, std::function<double()> now_s,
              RigLinkEvents events);
  ~RigctldLink() override;
  RigctldLink(const RigctldLink&) = delete;
  RigctldLink& operator=(const RigctldLink&) = delete;
  RigctldLink(RigctldLink&&) = delete;
  RigctldLink& operator=(RigctldLink&&) = delete;

  /// The session, to queue frequencies and reads; call flush() after queueing.
  radio::RigctlSession& session() { return session_; }
  [[nodiscard]] const radio::RigctlSession& session() const { return session_; }
  radio::RigPort& port() override { return session_; }
  /// Sends the next queued line if none is in flight.
  void flush() override;

  [[nodiscard]] RigLinkState state() const override { return state_; }
  /// Why the link is down ("" while up or before the first failure).
  [[nodiscard]] const std::string& down_reason() const override { return down_reason_; }
  [[nodiscard]] std::string describe() const override;

 private:
  void connect();
  void read();
  void poll();
  void on_line(const std::string& line);
  void lost(const std::string& why);

  boost::asio::ip::tcp::resolver resolver_;
  boost::asio::ip::tcp::socket socket_;
  boost::asio::steady_timer retry_timer_;
  boost::asio::steady_timer poll_timer_;
  boost::asio::streambuf in_;
  RigctldLinkConfig config_;
  std::function<double()> now_s_;
  RigLinkEvents events_;
  radio::RigctlSession session_;
  RigLinkState state_ = RigLinkState::Connecting;
  std::string down_reason_;
  double retry_s_;
  bool writing_ = false;
  bool down_reported_ = false;
  std::string out_;  ///< the line being written
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace azt::linux_os
