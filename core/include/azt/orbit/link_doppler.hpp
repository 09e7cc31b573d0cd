#pragma once
// The one-way Doppler of a satellite link, the one formula the program has (`azeltrack sat`, the
// radio's rig frequencies; docs/radio.md "Satellite Doppler"). Classical and exact in the ground
// frame, with the range rate ṙ in km/s, positive while the satellite recedes:
//   downlink, heard on the ground    f_ground = f_sat / (1 + ṙ/c)   the source moves away: lower
//   uplink, sent from the ground     f_ground = f_sat / (1 − ṙ/c)   the receiver moves away: send
//                                                                   higher so it hears f_sat
// The first-order forms f·(1 ∓ ṙ/c) (Gpredict's, csete/gpredict src/gtk-rig-ctrl.c:303-313)
// differ by f·(ṙ/c)²: 0.24 Hz at 435 MHz and 1.3 Hz at 2.4 GHz at 7 km/s. Relativity moves the
// frequency by as little (the satellite's clock at 7.7 km/s runs slow by 3.3e-10: 0.14 Hz at
// 435 MHz), and both are below any rig's step; the exact classical form is kept so that the
// program has one answer, checked against its closed form.

namespace azt::orbit {

/// Speed of light, km/s.
inline constexpr double kLightKmS = 299792.458;

/// The frequency heard on the ground for a satellite transmitting `satellite_hz`.
[[nodiscard]] constexpr double downlink_hz(double satellite_hz, double range_rate_km_s) {
  return satellite_hz / (1.0 + range_rate_km_s / kLightKmS);
}

/// The frequency to send from the ground for the satellite to receive `satellite_hz`.
[[nodiscard]] constexpr double uplink_hz(double satellite_hz, double range_rate_km_s) {
  return satellite_hz / (1.0 - range_rate_km_s / kLightKmS);
}

/// The satellite's transmit frequency heard on the ground at `ground_hz` (downlink_hz inverted).
[[nodiscard]] constexpr double satellite_downlink_hz(double ground_hz, double range_rate_km_s) {
  return ground_hz * (1.0 + range_rate_km_s / kLightKmS);
}

}  // namespace azt::orbit
