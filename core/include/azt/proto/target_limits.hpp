#pragma once
// The travel a PC-program protocol accepts targets in, shared by every server codec and session
// (rotctld, GS-232, EasyComm, PstRotator) so a station is configured once.
//
// Degrees. Azimuth is clockwise from north in the client's convention, so the range may extend
// below 0 (−180..180 clients) and beyond 360 (overlap rotators); elevation is up from the horizon
// and may exceed 90 on flip-over mounts. Bounds are inclusive. The defaults are Hamlib's dummy
// rotator, which rotctld announces in `\dump_state` (reference/rotator-controllers-and-protocols.md
// §3 and §8.1): az −180..450, el 0..90.

#include <string>

namespace azt::proto {

struct TargetLimits {
  double az_min_deg = -180.0;
  double az_max_deg = 450.0;
  double el_min_deg = 0.0;
  double el_max_deg = 90.0;

  /// False for NaN (every comparison with NaN is false).
  [[nodiscard]] constexpr bool accepts_az(double az_deg) const {
    return az_deg >= az_min_deg && az_deg <= az_max_deg;
  }
  [[nodiscard]] constexpr bool accepts_el(double el_deg) const {
    return el_deg >= el_min_deg && el_deg <= el_max_deg;
  }
  /// Why a value is refused ("az 500° is outside -180° to 450°"), "" when it is accepted: one
  /// wording for every protocol and the console, so an operator reads one reason.
  [[nodiscard]] std::string why_not_az(double az_deg) const;
  [[nodiscard]] std::string why_not_el(double el_deg) const;
};

}  // namespace azt::proto
