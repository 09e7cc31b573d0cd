#pragma once
// The one front door to the mode controller (docs/daemon.md). The console, every PC-program
// protocol and the configuration's start target reach the modes only through here, so they meet
// the same rules: the travel from [geometry], the same refusal while a fault is latched (each
// protocol answers it in its own error form, the console as 409, with the same reason), and a
// record of every accepted motion command with its source, so an operator can see who moved the
// antenna.

#include <functional>
#include <optional>
#include <string>

#include "antenna/antenna_backend.hpp"
#include "azt/control/axis_geometry.hpp"
#include "azt/control/modes.hpp"
#include "azt/proto/rotator_service.hpp"
#include "azt/proto/target_limits.hpp"
#include "common/target_request.hpp"
#include "station/satellite_tracker.hpp"
#include "station/sky_follower.hpp"

namespace azt::app {

/// Who asked. The kind decides what a position means (MAN from the console, EXT from a program)
/// and who a console STOP locks out (programs). Hands are the operator at the antenna: the
/// buttons at the mast and a game pad (docs/hardware.md); their moves are MAN, and their STOP
/// locks programs out as the console's does.
struct CommandSource {
  enum class Kind { Console, Program, Configuration, Schedule, Hands };
  Kind kind = Kind::Program;
  std::string name;  ///< "rotctld 127.0.0.1:51234", "console 127.0.0.1", "gs232b /dev/ttyUSB0"
};

/// Why a command was refused: its kind (Invalid: a value the station cannot take; Rejected: not
/// now; Unavailable: no position), the console's field at fault ("" for none) and the reason.
struct Refusal {
  proto::ServiceStatus status = proto::ServiceStatus::Invalid;
  std::string field;
  std::string reason;
};

/// What the station now does after an accepted command, or why it does not.
struct CommandOutcome {
  std::optional<Refusal> refusal;
  std::string mode;    ///< "TRACK", "MAN", "PARK", "EXT", "STOP" (accepted only)
  std::string target;  ///< what is commanded: "Moon", "sat:ISS (ZARYA)", "stow", … (accepted)
  [[nodiscard]] bool accepted() const { return !refusal.has_value(); }
};

/// An accepted motion command, for the record of who moved the antenna.
struct CommandRecord {
  std::string words;  ///< "position az 120.00° el 30.00°", "track Moon", "STOP"
  /// For commands a program repeats as a stream ("position", "continuous move"): records of one
  /// kind from one source may be counted as one. Empty for one-off commands (a target, a STOP).
  std::string stream_kind;
};

/// Who holds the antenna: the source of the last accepted command, and whether PC programs'
/// motion is taken now (/api/state `control`, the console's hand-over).
struct ControlHolder {
  std::string holder;  ///< "console", "pc", "configuration", "schedule" or "hands": the kind
  std::string by;      ///< its name: "console 192.168.1.20", "rotctld 127.0.0.1:51234"
  double since_unix_s = 0.0;
  bool pc_allowed = true;  ///< false while the console's STOP locks programs out
};

struct StationCommandParts {
  control::ModeController& modes;
  AntennaBackend& antenna;
  SkyFollower& sky;
  SatelliteTracker* satellites = nullptr;  ///< null: no satellite catalogue
  proto::TargetLimits limits;              ///< from [geometry] (DaemonConfig::target_limits)
  control::ElevationRange el_range;
  std::function<double()> monotonic_s;
  std::function<double()> unix_s;
  /// Where the mount's azimuth is when the sensors cannot say (for a pass's wrap side).
  double fallback_mount_az_deg = 0.0;
  /// Told of every accepted motion command, and of every refusal.
  std::function<void(const CommandSource&, const CommandRecord&)> accepted;
  std::function<void(const CommandSource&, const Refusal&)> refused;
};

class StationCommands {
 public:
  explicit StationCommands(StationCommandParts parts);

  /// Points the antenna at `request`: TRACK, MAN, PARK or EXT by the request and the source.
  CommandOutcome point(const CommandSource& source, const TargetRequest& request);
  /// A continuous move (EXT), stopped by the keep-alive when the program falls silent.
  CommandOutcome jog(const CommandSource& source, control::Jog jog);
  /// STOP, always accepted. The console's and the hands' latch PC programs out until the
  /// console chooses again.
  void stop(const CommandSource& source);
  /// The end of `source`'s continuous move (a button let go): STOP at once if the move is still
  /// `source`'s, nothing otherwise. Not recorded as a command: the move it ends was.
  void release(const CommandSource& source);
  /// "Allow PC control" (console only): EXT with nothing to move to until a program sends a
  /// position; lifts the console STOP's lock-out. Moves nothing.
  CommandOutcome allow_pc(const CommandSource& source);
  [[nodiscard]] ControlHolder control() const;
  /// A polarisation command (the console's POST /api/pol) meets the same rules as a motion
  /// command: refused (and reported) while a fault is latched, the E-stop among them, or, from
  /// a program, while programs are locked out. It does not change the az/el mode, who holds the
  /// antenna, or the schedule (the record of motion commands is for az/el). nullopt: it may go
  /// ahead.
  std::optional<Refusal> check_pol(const CommandSource& source);
  /// Any traffic from a program: the keep-alive of its continuous move.
  void heard_from(const CommandSource& source);
  /// A refusal decided before the front door (a session's malformed line): reported the same way.
  void report_refusal(const CommandSource& source, const Refusal& refusal);

  /// TRACK of a satellite (the satellite tracker gives the demand, not the sky follower).
  [[nodiscard]] bool tracking_satellite() const;
  /// The source of the present mode while it lasts; what the modes say once it changed by itself
  /// (a continuous move's keep-alive ran out).
  [[nodiscard]] std::string commander() const;

 private:
  [[nodiscard]] std::optional<Refusal> check_position(const PositionTarget& p) const;
  [[nodiscard]] std::optional<Refusal> check_now(const CommandSource& source) const;
  /// Applies a request that passed the checks; a refusal only for what only applying can find
  /// (a satellite with no pass, an unknown name).
  std::optional<Refusal> apply(const CommandSource& source, const TargetRequest& request);
  std::optional<Refusal> track_named(const NamedTarget& t);
  std::optional<Refusal> track_satellite(const SatelliteTarget& t);
  std::optional<Refusal> track_radec(const RaDecTarget& t);
  std::optional<Refusal> go_to(const CommandSource& source, const PositionTarget& p);
  std::optional<Refusal> park(const ParkTarget& t);
  /// Leaves the satellite tracker idle: another target or mode was chosen.
  void forget_satellite();
  /// How an applied request is recorded: a name as found ("track Cassiopeia A" for "casa").
  [[nodiscard]] CommandRecord record_of(const TargetRequest& request) const;
  CommandOutcome refuse(const CommandSource& source, Refusal refusal);
  CommandOutcome accept(const CommandSource& source, const CommandRecord& record);
  [[nodiscard]] std::string mode_signature() const;

  StationCommandParts p_;
  std::string commander_ = "configuration";
  CommandSource::Kind commander_kind_ = CommandSource::Kind::Configuration;
  double commander_since_unix_s_ = 0.0;
  std::string commander_signature_;
};

}  // namespace azt::app
