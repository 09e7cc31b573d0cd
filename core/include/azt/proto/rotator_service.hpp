#pragma once
// What a PC-program protocol session may ask of the station, and the session interface the
// daemon's transports (TCP, serial, pseudo-terminal, UDP) host.
//
// Sessions are pure: bytes in, bytes out, requests to a RotatorService. They never see a clock;
// the service stamps each request with its own time (for the continuous-move dead-man) and
// decides who is in control (EXT mode, console overrides).

#include <optional>
#include <string>
#include <string_view>

namespace azt::proto {

enum class Axis { Az, El };

/// Where the antenna points now. `az_deg` is the sky azimuth 0..360 (from north through east);
/// `az_mount_deg` is the mount angle, beyond 0..360 on overlap rotators.
struct PositionReport {
  double az_deg = 0.0;
  double el_deg = 0.0;
  double az_mount_deg = 0.0;
  bool moving = false;
  bool fault = false;  ///< a supervisor fault is latched: motion refused until cleared
};

/// How the station answered a request.
enum class ServiceStatus {
  Ok,
  Invalid,      ///< a value the station cannot take (outside the travel, not finite)
  Rejected,     ///< refused now: a fault is latched, or the console holds STOP
  Unavailable,  ///< no position (stale sensors): nothing is reported from a cache
};

/// A continuous move per axis: −1, 0 (hold that axis), +1. Azimuth +1 is clockwise, elevation +1
/// is up.
struct AxisMotion {
  int az = 0;
  int el = 0;
};

class RotatorService {
 public:
  RotatorService() = default;
  RotatorService(const RotatorService&) = delete;
  RotatorService& operator=(const RotatorService&) = delete;
  virtual ~RotatorService() = default;

  /// nullopt while the position is unknown (stale or faulted sensors).
  [[nodiscard]] virtual std::optional<PositionReport> position() const = 0;
  /// A position target (sky azimuth in any of the client's conventions: −180..450). Held until
  /// the next request; never extrapolated.
  virtual ServiceStatus goto_position(std::string_view client, double az_deg, double el_deg) = 0;
  /// One axis only; the other keeps its present target (or holds where it is).
  virtual ServiceStatus goto_axis(std::string_view client, Axis axis, double deg) = 0;
  /// A continuous move. It stops by itself when `client` sends nothing for 1 s.
  virtual ServiceStatus move(std::string_view client, AxisMotion motion) = 0;
  /// Stops both axes, or one.
  virtual void stop(std::string_view client, std::optional<Axis> axis) = 0;
  virtual ServiceStatus park(std::string_view client) = 0;
  /// Any traffic from `client`: the keep-alive of a continuous move.
  virtual void activity(std::string_view client) = 0;
  /// The session refused what `client` sent before it reached the station (a malformed line, a
  /// target outside the limits): the operator is told, the client got its protocol's error.
  virtual void refused(std::string_view client, std::string_view why) {
    (void)client;
    (void)why;
  }
  /// One line describing the station (rotctld `_`, EasyComm `VE`).
  [[nodiscard]] virtual std::string info() const = 0;
};

/// One client's conversation in one protocol.
class ProtocolSession {
 public:
  ProtocolSession() = default;
  ProtocolSession(const ProtocolSession&) = delete;
  ProtocolSession& operator=(const ProtocolSession&) = delete;
  virtual ~ProtocolSession() = default;

  /// Feeds received bytes; returns the bytes to send back (possibly none). Every complete
  /// command is answered, in order, in one string, so a transport can send it in one write.
  virtual std::string feed(std::string_view bytes) = 0;
  /// True once the client asked to end the conversation (rotctld `q`): close after sending.
  [[nodiscard]] virtual bool finished() const { return false; }
};

}  // namespace azt::proto
