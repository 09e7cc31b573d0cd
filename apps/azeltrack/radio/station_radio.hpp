#pragma once
// The station's radio (docs/radio.md "In the daemon"): the rig (or two) through rigctld or
// libhamlib (rig_links.hpp), the Doppler cycle every 200 ms, and WSJT-X's UDP messages. On the
// daemon's loop; nothing here waits for a rig or a datagram. The radio never keys a transmitter.

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "azt/astro/ephemeris.hpp"
#include "azt/linux/asio.hpp"
#include "azt/linux/rig_connection.hpp"
#include "azt/radio/rigctl_session.hpp"
#include "config/radio_config.hpp"
#include "config/sky_config.hpp"
#include "radio/rig_doppler_cycle.hpp"
#include "radio/wsjtx_listener.hpp"

namespace azt::app {

struct StationRadioParts {
  RadioConfig radio;
  WsjtxConfig wsjtx;
  const astro::Ephemeris& ephemeris;
  const SkyConfig& sky;  ///< the running sky (its DX may follow WSJT-X)
  std::function<double()> monotonic_s;
  std::function<double()> unix_s;
  /// The tracked satellite now (none: no satellite tracked).
  std::function<std::optional<SatelliteNow>()> satellite;
  /// WSJT-X's DX grid, to become the running DX (not saved).
  std::function<void(const std::string& grid)> dx_grid;
  std::function<void(const std::string&)> log;
};

class StationRadio {
 public:
  static constexpr double kCycleS = 0.2;

  /// Starts the rig links and the cycle; throws UsageError when [wsjtx] listen cannot be bound.
  StationRadio(boost::asio::io_context& io, StationRadioParts parts);
  ~StationRadio();
  StationRadio(const StationRadio&) = delete;
  StationRadio& operator=(const StationRadio&) = delete;

  /// WSJT-X asks the antenna to hold (transmitting, or outside the move window).
  [[nodiscard]] bool motion_hold() const { return wsjtx_.motion_hold(); }
  [[nodiscard]] bool wsjtx_transmitting() const { return wsjtx_.transmitting(); }
  /// `/api/state` `radio`: {doppler, link, tx_link, rx_hz, tx_hz, at, at_unix_s,
  /// rx_correction_hz, tx_correction_hz, problem}
  [[nodiscard]] nlohmann::json radio_json() const;
  /// `/api/state` `wsjtx`
  [[nodiscard]] nlohmann::json wsjtx_json() const { return wsjtx_.to_json(); }
  void close();

 private:
  std::unique_ptr<linux_os::RigConnection> make_link(RigRole role);
  void on_link(RigRole role, linux_os::RigLinkState state, const std::string& why,
               const std::string& name);
  void cycle();
  void arm();
  [[nodiscard]] std::optional<radio::EchoDoppler> echo_at(double unix_s) const;

  StationRadioParts p_;
  boost::asio::io_context& io_;
  boost::asio::steady_timer timer_;
  std::unique_ptr<linux_os::RigConnection> main_;
  std::unique_ptr<linux_os::RigConnection> uplink_;
  radio::RigctlSession idle_session_;  ///< stands in for the rig when none is configured
  std::unique_ptr<RigDopplerCycle> cycle_;
  WsjtxListener wsjtx_;
  bool closed_ = false;
};

/// A link as the state says it: "off", "connecting", "up" or "down: why".
std::string link_text(const linux_os::RigConnection* link);

}  // namespace azt::app
