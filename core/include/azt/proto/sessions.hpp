#pragma once
// Protocol sessions: one client's conversation in rotctld, GS-232, EasyComm or SPID, joining a
// pure codec (rotctld.hpp, gs232.hpp, easycomm.hpp, spid.hpp) to a RotatorService. Bytes in, bytes
// out; no clock, no I/O, no logging (the transport logs). PstRotator is datagram-based and has no
// session: see handle_pstrotator_datagram in pstrotator.hpp.
//
// Common rules:
//   - Every complete command (line or frame, including rotctld comment lines, GS-232's empty line
//     and overlong lines) first calls service.activity(client): any traffic keeps a continuous move
//     alive, so a client that polls the position keeps its move running, as on a real controller.
//   - Replies report PositionReport::az_deg, the sky azimuth 0..360, never the mount angle.
//   - Speed arguments (rotctld `M`, GS-232 `X1`..`X4`) are accepted and ignored: the station
//     moves at its configured rates.
//
// Per protocol (the reference is reference/rotator-controllers-and-protocols.md §8.1-§8.4):
//   rotctld: ServiceStatus Ok/Invalid/Rejected/Unavailable is sent as RPRT 0/-1/-9/-6. An unknown
//     position answers `p` with RPRT -6 and keeps the connection (Hamlib closes it). `R` (reset)
//     stops both axes and answers RPRT 0. After `q` the session is finished: the rest of that
//     feed is neither executed nor answered.
//   GS-232: a refused W/M/L/R/U/D (any status but Ok) and an overlong line answer "?>\r\n", the
//     controller's only error reply. X, P36/P45, Z, O/F/O2/F2 and H/H2 are acknowledged as the
//     codec formats them and change nothing. L/R/U/D are the service's continuous moves, so unlike
//     a real controller they stop after 1 s without traffic; a client polling C2 keeps them going.
//   EasyComm: set tokens of one line are one request (goto_position for AZ+EL, goto_axis for
//     one), move tokens one move() with the axes combined, SA+SE one stop(both), made in the order
//     stop, target, move, park. RESET stops. A refused request is not reported (EasyComm has no
//     reply for it; GS shows the station's state).
//     Lines that fail to parse and set-only lines get no reply (EasyComm has no error reply).
//     While the position is unknown, AZ/EL queries are answered with the error status "GS8 GE1"
//     (EasyComm III: status error, error sensor) instead of angles, so Hamlib fails at once
//     (RIG_ERJCTED) rather than after its read timeout; GS/GE queries report 8/1 too, as they do
//     for a latched fault (otherwise GS is 2 while moving, else 1, and GE 0). VE answers
//     service.info() with line breaks replaced by spaces.
//   SPID: a set gets no reply (the real controller sends none); stop and status reply with the
//     position frame. A bad frame, or a stop/status while the position is unknown (or does not
//     fit the frame), gets no reply: SPID has no error frame, the client times out.

#include <memory>
#include <string>

#include "azt/proto/easycomm.hpp"
#include "azt/proto/gs232.hpp"
#include "azt/proto/rotator_service.hpp"
#include "azt/proto/spid.hpp"
#include "azt/proto/target_limits.hpp"

namespace azt::proto {

std::unique_ptr<ProtocolSession> make_rotctld_session(RotatorService& service, std::string client,
                                                      TargetLimits limits);

std::unique_ptr<ProtocolSession> make_gs232_session(RotatorService& service, std::string client,
                                                    Gs232Variant variant, TargetLimits limits);

std::unique_ptr<ProtocolSession> make_easycomm_session(RotatorService& service, std::string client,
                                                       EasyCommVersion version,
                                                       TargetLimits limits);

/// The set range is SpidConfig's (the emulated controller's), not a TargetLimits.
std::unique_ptr<ProtocolSession> make_spid_session(RotatorService& service, std::string client,
                                                   SpidConfig config);

/// The ServiceStatus of a request as a rotctld RPRT code.
int rprt_code(ServiceStatus status);

}  // namespace azt::proto
