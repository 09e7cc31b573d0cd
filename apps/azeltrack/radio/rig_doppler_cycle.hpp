#pragma once
// What the station writes to its rig each radio cycle (docs/radio.md "In the daemon"): the
// tracked satellite's transmitter through the core's SatelliteDopplerPlanner, or the Moon's echo
// Doppler through WSJT-X's EME modes (azt/radio/eme_doppler_modes.hpp). No I/O of its own: it
// queues frequencies on one or two RigPorts (rigctld's sessions or libhamlib's workers carry
// them) and is told what the rigs answered, so the tests drive it with sessions fed by hand and a
// clock of their own.
//
// EME writes: a leg is written when its whole-Hz frequency differs from the last queued one
// (rigctld takes whole Hz; the echo Doppler at 1296 MHz moves by a few Hz a minute, so this is a
// few writes a minute and the rig is always within 1 Hz of the correction computed). With
// no_tx_qsy the TX correction is computed once per T/R period for the middle of the next one and
// written before keying (WSJT-X's rule, TxOncePerPeriod).
//
// The state's rx_hz / tx_hz are what a rig acknowledged (RPRT 0 to the set), each with the UTC
// instant it was computed for (`at`, `tx_at`: the legs are written on their own): the value queued
// last when the acknowledgement came (the session keeps at most one write queued, and a cycle every
// 200 ms against a rig that answers in tens of ms leaves nothing to coalesce).

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "azt/radio/eme_doppler_modes.hpp"
#include "azt/radio/rig_port.hpp"
#include "azt/radio/satellite_doppler_planner.hpp"
#include "config/radio_config.hpp"

namespace azt::app {

/// The tracked satellite now.
struct SatelliteNow {
  std::string norad;
  double range_rate_km_s = 0.0;
};

/// What one cycle knows of the world.
struct RadioInputs {
  double now_s = 0.0;   ///< monotonic
  double unix_s = 0.0;  ///< UTC seconds since 1970
  std::optional<SatelliteNow> satellite;
  /// The Moon's echo Doppler at the dial frequency at a UTC instant (none: no Moon, no ephemeris).
  std::function<std::optional<radio::EchoDoppler>(double unix_s)> echo_at;
  bool transmitting = false;          ///< WSJT-X says so (no_tx_qsy)
  std::optional<double> tr_period_s;  ///< WSJT-X's T/R period, when it gave one
};

/// Which rig an answer came from.
enum class RigRole { Main, Uplink };

/// A frequency a rig acknowledged, and the UTC instant it was computed for.
struct WrittenHz {
  double hz = 0.0;
  double at_unix_s = 0.0;
  double correction_hz = 0.0;  ///< the Doppler part of it
};

class RigDopplerCycle {
 public:
  /// `uplink`: the second rig ([radio] tx_rigctld or tx_model), or null: the uplink is `main`'s
  /// split VFO.
  RigDopplerCycle(const RadioConfig& config, radio::RigPort& main, radio::RigPort* uplink);

  /// One cycle: queues what is due on the sessions (the caller flushes them).
  void run(const RadioInputs& in);
  /// An answer from a rig; `now_s` (monotonic) times the planner's writes.
  void on_event(RigRole role, const radio::RigEvent& event, double now_s);
  /// A rig's link came up: everything is written afresh.
  void on_connected(RigRole role);

  [[nodiscard]] const std::optional<WrittenHz>& rx() const { return rx_.written; }
  [[nodiscard]] const std::optional<WrittenHz>& tx() const { return tx_.written; }
  /// Why nothing is written now ("" when all is well): no satellite, no transmitter, no DX grid.
  [[nodiscard]] const std::string& problem() const { return problem_; }
  /// The tracked satellite's transmitter the last cycle followed, or null.
  [[nodiscard]] const TransmitterConfig* transmitter() const { return transmitter_; }
  /// {doppler, rigctld, tx_rigctld, eme_mode, transmitter, rx_hz, tx_hz, at, at_unix_s (rx_hz's
  /// instant, else tx_hz's), tx_at, tx_at_unix_s, rx_correction_hz, tx_correction_hz, problem}
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  struct Leg {
    std::optional<WrittenHz> queued;
    std::optional<WrittenHz> written;
    bool readback_due = false;  ///< the read after an acknowledged write is the rig's value
  };
  /// A satellite cycle's moment, kept while its dial read is answered.
  struct SatelliteCycle {
    double now_s = 0.0;
    double unix_s = 0.0;
    double range_rate_km_s = 0.0;
  };
  void run_satellite(const RadioInputs& in);
  void plan_satellite(const SatelliteCycle& at, std::optional<double> dial_hz);
  void on_read(Leg& leg, bool tx_leg, double hz, double now_s);
  void run_eme(const RadioInputs& in);
  void eme_tx(const RadioInputs& in, const radio::EchoDoppler& now_echo);
  bool queue_rx(double hz, double at_unix_s, double correction_hz);
  bool queue_tx(double hz, double at_unix_s, double correction_hz);
  [[nodiscard]] static bool differs(const Leg& leg, double hz);
  void set_problem(std::string problem) { problem_ = std::move(problem); }

  const RadioConfig& config_;
  radio::RigPort& main_;
  radio::RigPort* uplink_;
  Leg rx_;
  Leg tx_;
  /// Track the knob: the cycle whose dial read is in flight; it is planned on the answer.
  std::optional<SatelliteCycle> awaiting_dial_;
  std::string planner_norad_;
  const TransmitterConfig* transmitter_ = nullptr;  ///< in config_, which outlives the cycle
  std::unique_ptr<radio::SatelliteDopplerPlanner> planner_;
  radio::TxOncePerPeriod tx_period_;
  std::string problem_;
};

}  // namespace azt::app
