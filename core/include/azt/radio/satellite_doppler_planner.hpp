#pragma once
// What to write to the rig each cycle during a satellite pass: the Doppler-corrected RX and TX
// (satellite_doppler.hpp), "track the knob" for linear transponders, and when a write is due.
//
// Track the knob (Gpredict's dial feedback, csete/gpredict src/gtk-rig-ctrl.c:1690-1726): each
// cycle the caller reads the main VFO. If it differs from what was last written (as read back:
// rigs round to their step) by 1 Hz or more, the operator turned the knob: the satellite-frame
// downlink becomes what is heard at the dial now (satellite_downlink_hz at the current range
// rate), the satellite-frame uplink follows through the passband relation, and that cycle the RX
// is not written (the rig is where the operator put it; writing it would fight the knob) while
// the TX follows. An FM transmitter ignores the dial: its channel does not move, and the next
// write puts the rig back on it.
//
// Update rule: a leg is written when its wanted frequency moved by more than the step from the
// last written value, or by at least 1 Hz and the last write is max_interval_s old, or when
// nothing was written yet. The step is quoted at 435 MHz and scaled with the leg's frequency
// (scaled_step_hz): default 10 Hz. Called once a second this writes every change of 1 Hz or more
// (what Gpredict does, with its 1 s cycle); called faster, the step decides: near the closest
// approach of a high pass the range rate changes by up to about 0.1 km/s² [computed], 145 Hz/s at
// 435 MHz, so a 10 Hz step keeps the rig within 10 Hz where a 1 s cycle lets it lag 145 Hz.
// The rigctl session coalesces writes that arrive faster than the rig answers. Others: SatPC32
// users set 50-100 Hz for SSB, CardSat 50 Hz SSB / 300 Hz FM.

#include <optional>

#include "azt/radio/satellite_doppler.hpp"

namespace azt::radio {

struct DopplerUpdateRule {
  double step_hz_at_435_mhz = 10.0;
  double max_interval_s = 1.0;
};

struct SatelliteRigPlan {
  double satellite_downlink_hz = 0.0;  ///< the operator's place in the passband (satellite frame)
  std::optional<double> satellite_uplink_hz;
  double rx_hz = 0.0;  ///< the rig's RX for now
  std::optional<double> tx_hz;
  bool write_rx = false;
  bool write_tx = false;
  bool knob_moved = false;  ///< this cycle's dial read showed the operator tuning
};

class SatelliteDopplerPlanner {
 public:
  explicit SatelliteDopplerPlanner(SatelliteTransmitter transmitter, DopplerUpdateRule rule = {})
      : transmitter_(transmitter), rule_(rule), satellite_downlink_hz_(transmitter.downlink_hz) {}

  /// One cycle at `now_s` (any monotonic seconds): `dial_rx_hz` is the main VFO just read, or
  /// nullopt when it was not read this cycle.
  SatelliteRigPlan plan(double now_s, double range_rate_km_s, std::optional<double> dial_rx_hz);
  /// The rig's frequencies after a write, as read back.
  void rx_written(double now_s, double rig_rx_hz);
  void tx_written(double now_s, double rig_tx_hz);
  /// Forget what was written (a new connection, PTT changed, the transmitter changed): the next
  /// plan writes both legs and reads no knob movement (Gpredict's lastrxf = 0, :1773-1783).
  void forget_written();
  /// The operator's place goes back to the transmitter's nominal downlink.
  void recentre() { satellite_downlink_hz_ = transmitter_.downlink_hz; }

  [[nodiscard]] double satellite_downlink_hz() const { return satellite_downlink_hz_; }

 private:
  struct Leg {
    std::optional<double> hz;  ///< last written, as read back
    double at_s = 0.0;
  };
  [[nodiscard]] bool tracks_knob() const;
  [[nodiscard]] bool due(const Leg& leg, double wanted_hz, double now_s) const;

  SatelliteTransmitter transmitter_;
  DopplerUpdateRule rule_;
  double satellite_downlink_hz_;
  Leg rx_;
  Leg tx_;
};

/// Whether a dial read shows the operator tuning: 1 Hz or more from what was last written.
bool knob_moved(double dial_hz, double last_written_hz);

}  // namespace azt::radio
