#pragma once
// Satellite Doppler for a rig: which satellite-frame frequencies the rig's two legs follow. The
// Doppler itself is the orbit's one formula (azt/orbit/link_doppler.hpp: heard f/(1 + ṙ/c), sent
// f/(1 − ṙ/c), ṙ positive receding), so the rig and `azeltrack sat` agree to the hertz.
//
// Linear transponders: a signal sent at uplink u (satellite frame) comes down at d. The pair
// keeps the relation of the transponder's passband (Gpredict's track_downlink/track_uplink,
// gtk-rig-ctrl.c:340-387, there written with the passband edges):
//   non-inverting   u − d = U − D   (constant difference)
//   inverting       u + d = U + D   (constant sum)
// where (D, U) is any matching pair of the transmitter, e.g. the centres of its two passbands
// (with edges, D_low + U_high for inverting, the same sum when both passbands are equally wide).
// Doppler is applied to each leg afterwards, so the operator hears their own signal where they
// transmit it (the CardSat 0.9.16 release notes describe the error of holding one rig leg fixed).

#include <optional>

namespace azt::radio {

/// The frequency at which step sizes are quoted (the 70 cm satellite band; Gpredict and SatPC32
/// users quote their steps there).
inline constexpr double kStepReferenceHz = 435e6;

enum class TransponderMode {
  Fm,               ///< a channel: FM voice, CW or data; RX and TX stay on the nominal pair
  Linear,           ///< non-inverting passband: the dial moves both legs the same way
  LinearInverting,  ///< inverting passband: the uplink moves opposite to the downlink
};

/// One transmitter of a satellite (`[[satellites.transmitter]]`): its nominal frequencies in the
/// satellite's frame. For a linear transponder the pair must match (a signal sent at
/// uplink_hz comes down at downlink_hz).
struct SatelliteTransmitter {
  double downlink_hz = 0.0;
  std::optional<double> uplink_hz;  ///< none: receive only
  TransponderMode mode = TransponderMode::Fm;
};

/// The satellite-frame uplink that comes down at `satellite_downlink_hz`: the passband relation
/// above for linear transponders; the nominal uplink for FM (its channel does not move). nullopt
/// for a receive-only transmitter.
std::optional<double> paired_uplink_hz(const SatelliteTransmitter& transmitter,
                                       double satellite_downlink_hz);

/// A step quoted at 435 MHz scaled to `freq_hz`: Doppler and its rate are proportional to the
/// frequency, so the same step in proportion keeps the same time between writes on every band
/// (10 Hz at 435 MHz is 3.3 Hz at 145 MHz and 55 Hz at 2.4 GHz). Never below 1 Hz, the smallest
/// step rigctld takes.
double scaled_step_hz(double step_hz_at_435_mhz, double freq_hz);

}  // namespace azt::radio
