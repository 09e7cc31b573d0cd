#pragma once
// What WSJT-X says over UDP (docs/radio.md "WSJT-X"), decoded with the core's wsjtx_message and
// kept for the station: the DX call and grid of its Status, whether it transmits, its T/R period.
// Malformed datagrams (and oversized ones) are counted and logged at most once a minute, never
// fatal.
//
// Transmitting holds the antenna as the PTT input does. WSJT-X sends a Status on every change
// (the start and the end of a transmission) and a Heartbeat every 15 s (NetworkMessage.hpp,
// `pulse`), but nothing while a transmission goes on. So the hold ends with a Status that says
// not transmitting, a Close, or silence: nothing heard from WSJT-X for kStaleS = 20 s (one
// heartbeat missed plus 5 s) means it died mid-transmission, and the hold lifts rather than hold
// the antenna for ever.
//
// move_in_last_s (K3NG #62's "move only at the end of the period"): with a T/R period known,
// motion is held except in the last move_in_last_s seconds of each period (periods start at
// multiples of the period in UTC seconds, as WSJT-X counts them). The period is the Status's, or
// the one WSJT-X fixes for its mode when the Status does not say it (FT8, FT4:
// azt/radio/wsjtx_tr_period.hpp).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "azt/linux/asio.hpp"
#include "azt/linux/udp_receiver.hpp"
#include "azt/radio/wsjtx_message.hpp"
#include "config/wsjtx_config.hpp"

namespace azt::app {

struct WsjtxParts {
  WsjtxConfig config;
  std::function<double()> monotonic_s;
  std::function<double()> unix_s;
  /// A DX grid WSJT-X gave (follow_dx_grid): the running DX follows; false when refused.
  std::function<void(const std::string& grid)> dx_grid;
  std::function<void(const std::string&)> log;
};

class WsjtxListener {
 public:
  static constexpr double kStaleS = 20.0;

  explicit WsjtxListener(WsjtxParts parts);
  /// Opens the socket ([wsjtx] listen); the error names the address.
  Result<bool> open(boost::asio::io_context& io);
  void close();

  /// One datagram as received (the socket's handler; the tests call it directly).
  void on_datagram(std::string_view datagram);
  void on_oversized(std::size_t bytes);

  /// WSJT-X transmits now (the last Status said so, and WSJT-X is not silent for kStaleS).
  [[nodiscard]] bool transmitting() const;
  /// The antenna must not move: transmitting (hold_motion_while_transmitting), or outside the
  /// last move_in_last_s of the period.
  [[nodiscard]] bool motion_hold() const;
  [[nodiscard]] std::optional<double> tr_period_s() const { return tr_period_s_; }
  [[nodiscard]] std::uint64_t malformed() const { return malformed_; }
  [[nodiscard]] unsigned short port() const { return socket_ ? socket_->port() : 0; }
  /// {listening, last_heard, id, dx_call, dx_grid, transmitting, transmitting_since_unix_s, hold,
  /// tr_period_s, received: {heartbeat, status, close, other}, malformed, last_malformed}
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  void on_status(const radio::WsjtxStatus& status);
  void on_close(const radio::WsjtxClose& close);
  void malformed(const std::string& why);
  void heard(const std::string& id);

  WsjtxParts p_;
  std::unique_ptr<linux_os::UdpReceiver> socket_;
  std::optional<double> last_heard_mono_s_;
  std::optional<double> last_heard_unix_s_;
  std::string id_;
  std::string dx_call_;
  std::string dx_grid_;
  bool transmitting_ = false;
  std::optional<double> transmitting_since_unix_s_;  ///< set whenever transmitting_ is
  std::optional<double> tr_period_s_;
  /// The datagrams decoded, by type (other: the types recognised and not read, Decode and the
  /// like).
  struct Received {
    std::uint64_t heartbeat = 0;
    std::uint64_t status = 0;
    std::uint64_t close = 0;
    std::uint64_t other = 0;
  } received_;
  std::uint64_t malformed_ = 0;
  std::string last_malformed_;
  std::optional<double> malformed_logged_at_s_;
};

}  // namespace azt::app
