#include "azt/radio/satellite_doppler_planner.hpp"

#include <cmath>

#include "azt/orbit/link_doppler.hpp"

namespace azt::radio {

bool knob_moved(double dial_hz, double last_written_hz) {
  return std::abs(dial_hz - last_written_hz) >= 1.0;
}

bool SatelliteDopplerPlanner::tracks_knob() const {
  return transmitter_.mode != TransponderMode::Fm;
}

bool SatelliteDopplerPlanner::due(const Leg& leg, double wanted_hz, double now_s) const {
  if (!leg.hz) return true;
  const double moved_hz = std::abs(wanted_hz - *leg.hz);
  if (moved_hz > scaled_step_hz(rule_.step_hz_at_435_mhz, wanted_hz)) return true;
  return moved_hz >= 1.0 && now_s - leg.at_s >= rule_.max_interval_s;
}

SatelliteRigPlan SatelliteDopplerPlanner::plan(double now_s, double range_rate_km_s,
                                               std::optional<double> dial_rx_hz) {
  SatelliteRigPlan out;
  out.knob_moved = tracks_knob() && dial_rx_hz && rx_.hz && knob_moved(*dial_rx_hz, *rx_.hz);
  if (out.knob_moved) {
    satellite_downlink_hz_ = orbit::satellite_downlink_hz(*dial_rx_hz, range_rate_km_s);
    rx_.hz = *dial_rx_hz;  // the rig is there now: the next knob turn is measured from here
  }
  out.satellite_downlink_hz = satellite_downlink_hz_;
  out.satellite_uplink_hz = paired_uplink_hz(transmitter_, satellite_downlink_hz_);
  out.rx_hz = orbit::downlink_hz(satellite_downlink_hz_, range_rate_km_s);
  out.write_rx = !out.knob_moved && due(rx_, out.rx_hz, now_s);
  if (out.satellite_uplink_hz) {
    out.tx_hz = orbit::uplink_hz(*out.satellite_uplink_hz, range_rate_km_s);
    out.write_tx = due(tx_, *out.tx_hz, now_s);
  }
  return out;
}

void SatelliteDopplerPlanner::rx_written(double now_s, double rig_rx_hz) {
  rx_.hz = rig_rx_hz;
  rx_.at_s = now_s;
}

void SatelliteDopplerPlanner::tx_written(double now_s, double rig_tx_hz) {
  tx_.hz = rig_tx_hz;
  tx_.at_s = now_s;
}

void SatelliteDopplerPlanner::forget_written() {
  rx_ = Leg();
  tx_ = Leg();
}

}  // namespace azt::radio
