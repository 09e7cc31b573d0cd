#pragma once
// PstRotator UDP, server side: azeltrack stands in for PstRotator for Hamlib's PstRotator backend
// (rot_pstrotator.c; not in Debian 12's Hamlib 4.5.4) and the many scripts that speak its `<PST>`
// datagrams (reference/rotator-controllers-and-protocols.md
// §8.6; Hamlib rigs/dummy/rot_pstrotator.c).
//
// One datagram is one command: `<PST>` ... `</PST>` (tag names case-insensitive, whitespace
// around items allowed) holding any of
//   <AZIMUTH>a</AZIMUTH>  <ELEVATION>e</ELEVATION>   targets, degrees; both may appear
//   <STOP>1</STOP>        <PARK>1</PARK>             (a value of 0 is accepted and does nothing)
//   AZ?                   EL?                        position queries
//   <TRACK>0|1</TRACK>  <ON>0|1</ON>  <QRA>locator</QRA>   accepted and ignored (PstRotator UI)
// Anything else (other tags, junk, an unclosed tag, a datagram over kPstMaxDatagramBytes) makes the
// whole datagram an error and nothing of it is applied.
//
// Numbers are read by numeric prefix, `[+-]digits[.digits]`, because Hamlib formats targets as
// "%f.2" and so sends "123.000000.2"; after the prefix only such a `.digits` tail is tolerated.
// NaN, infinities, exponents and targets outside the TargetLimits are errors.
//
// Replies (sent by the transport to the client's port + 1, 12001 by default) are "AZ:123.4\r" and
// "EL:45.6\r": one decimal, CR-terminated, as PstRotator and its emulators send; Hamlib reads them
// with sscanf "AZ:%g" / "EL:%g" after cutting the datagram at the first CR or LF.
//
// Deviations from PstRotator, where it differs from what a client can rely on:
//   - A datagram asking both AZ? and EL? gets one reply holding both lines ("AZ:..\rEL:..\r").
//     Hamlib asks in two datagrams and reads only the first line of each reply.
//   - While the position is unknown, AZ?/EL? get no reply (the protocol has no error reply; Hamlib
//     keeps its last value and logs a timeout), and the reported azimuth is the sky azimuth
//     0..360 (PositionReport::az_deg).
//   - Refused targets (ServiceStatus other than Ok) are not reported: UDP commands get no reply.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "azt/proto/rotator_service.hpp"
#include "azt/proto/target_limits.hpp"
#include "azt/util/result.hpp"

namespace azt::proto {

/// Longest datagram accepted; real commands are under 64 bytes.
inline constexpr std::size_t kPstMaxDatagramBytes = 512;

struct PstCommand {
  std::optional<double> az_deg;  ///< <AZIMUTH>
  std::optional<double> el_deg;  ///< <ELEVATION>
  bool stop = false;             ///< <STOP>1</STOP>
  bool park = false;             ///< <PARK>1</PARK>
  bool query_az = false;         ///< AZ?
  bool query_el = false;         ///< EL?
  bool operator==(const PstCommand&) const = default;
};

/// Parses one datagram. Pure and locale-free.
Result<PstCommand> parse_pstrotator(std::string_view datagram, const TargetLimits& limits = {});

/// "AZ:123.4\r" for name "AZ": one decimal, never "-0.0"; empty if `deg` is not finite.
std::string format_pstrotator_angle(std::string_view name, double deg);

/// Applies one datagram from `client` to `service` and returns the reply datagram, or an empty
/// string when nothing is to be sent. Every datagram, even a bad one, counts as activity. Requests
/// are made in the order stop, target (goto_position for both angles, goto_axis for one), park.
std::string handle_pstrotator_datagram(std::string_view datagram, RotatorService& service,
                                       std::string_view client, const TargetLimits& limits);

}  // namespace azt::proto
