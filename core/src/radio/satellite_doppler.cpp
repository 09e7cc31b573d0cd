#include "azt/radio/satellite_doppler.hpp"

#include <algorithm>
#include <cmath>

namespace azt::radio {

std::optional<double> paired_uplink_hz(const SatelliteTransmitter& transmitter,
                                       double satellite_downlink_hz) {
  if (!transmitter.uplink_hz) return std::nullopt;
  const double moved_hz = satellite_downlink_hz - transmitter.downlink_hz;
  switch (transmitter.mode) {
    case TransponderMode::Fm:
      return *transmitter.uplink_hz;
    case TransponderMode::Linear:
      return *transmitter.uplink_hz + moved_hz;
    case TransponderMode::LinearInverting:
      return *transmitter.uplink_hz - moved_hz;
  }
  return std::nullopt;
}

double scaled_step_hz(double step_hz_at_435_mhz, double freq_hz) {
  return std::max(1.0, step_hz_at_435_mhz * std::abs(freq_hz) / kStepReferenceHz);
}

}  // namespace azt::radio
