#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "azt/util/result.hpp"

namespace azt::control {

/// The seed's operating modes: TRACK a sky target, MAN(ual) move to a typed az/el (not
/// persistent), PARK in one of four named slots, EXT(ernal) position from a PC program, STOP
/// (latched, motors off).
enum class Mode { Track, Manual, Park, External, Stop };
std::string_view to_string(Mode mode);

/// What to do when the tracked target is below the horizon limit or outside the travel.
enum class OutOfRangePolicy { Hold, Park };

struct AzEl {
  double az_deg = 0.0;  ///< sky azimuth, from north through east
  double el_deg = 0.0;
};

struct ParkSlot {
  std::string name;
  AzEl position;
};

/// A continuous move per axis: −1, 0 (hold that axis), +1. Azimuth +1 is clockwise, elevation
/// +1 is up. The axes run towards the end of their travel until stopped, each at its speed: a
/// fraction of the axis's full rate (a PC program's move is at full speed; a game pad's stick
/// asks for its deflection).
struct Jog {
  int az = 0;
  int el = 0;
  double az_speed = 1.0;  ///< 0 < speed ≤ 1 on a moving axis
  double el_speed = 1.0;
};

/// The direction test of one axis (docs/hardware.md): driven open loop, slowly, one way, so the
/// way its reading goes shows a motor or sensor wired the wrong way round. The other axis holds.
struct AxisTest {
  bool azimuth = true;
  int direction = 1;  ///< +1 clockwise / up, −1 the other way
};

/// Where the antenna should point now, and why.
struct Demand {
  std::optional<AzEl> position;  ///< nullopt: do not move (STOP, or holding)
  std::string reason;            ///< for the status line: "tracking Moon", "holding: Moon set"
  std::optional<Jog> jog;        ///< a continuous move (EXT `M`); `position` is then nullopt
  /// `position` is in mount angles (azimuth counting past 360 on overlap rotators, elevation up to
  /// 180 on flip mounts), chosen by a pass plan: driven as given, never re-planned to the nearest
  /// side, so a pass never unwinds mid-way.
  bool mount = false;
  std::optional<AxisTest> test =
      std::nullopt;  ///< a direction test; `position` and `jog` are then nullopt
};

/// Which mode is active and what it asks for. Pure: the tracker feeds it the sky position of the
/// tracked target each tick; it never computes astronomy itself.
class ModeController {
 public:
  static constexpr int kParkSlots = 4;
  static constexpr double kJogKeepAliveS = 1.0;

  ModeController(std::array<ParkSlot, kParkSlots> slots, OutOfRangePolicy policy, double min_el_deg)
      : slots_(std::move(slots)), policy_(policy), min_el_deg_(min_el_deg) {}

  void track(std::string target_name);
  Result<Mode> manual(AzEl position);
  Result<Mode> park(int slot);  ///< 1..4
  Result<Mode> external(AzEl position, std::string client);
  /// A continuous move from a PC program. It needs a keep-alive: when `client` has not been
  /// heard from for kJogKeepAliveS the move stops (reference R11: rotctld itself never stops).
  Result<Mode> external_jog(Jog jog, std::string client, double now_s);
  /// A continuous move by an operator at the station (the buttons at the mast, a game pad): MAN,
  /// with the same keep-alive, and not refused after a console STOP (that locks out PC programs,
  /// not the people at the antenna).
  Result<Mode> manual_jog(Jog jog, std::string client, double now_s);
  /// Ends `client`'s continuous move at once (a button let go): STOP, "released by CLIENT".
  /// Nothing happens if the move is not `client`'s (another source took over meanwhile).
  void end_jog(std::string_view client);
  /// Any traffic from a PC program (a `p` poll counts).
  void heard_from(std::string_view client, double now_s);
  /// Applies the jog dead-man; call once per tick.
  void update(double now_s);
  /// STOP. From the console it is latched against PC programs: their targets are refused until
  /// the console chooses a mode again (the user's STOP must not be undone by a polling program).
  void stop(bool from_console = false);
  /// STOP from an operator at the station (the STOP button at the mast): latched against PC
  /// programs as the console's is, so a polling program cannot move the antenna under the hands
  /// of whoever pressed it; `who` names the button.
  void local_stop(std::string_view who);
  /// "Allow PC control" from the console: EXT with no position yet, so nothing moves until a PC
  /// program sends one, and the console's STOP no longer locks programs out. The hand-over that
  /// TRACK, MAN or PARK would give only by moving the antenna.
  void allow_external();
  [[nodiscard]] bool external_locked() const { return external_locked_; }
  /// The position targets set by MAN, PARK and EXT (nullopt in TRACK and STOP, and while jogging).
  [[nodiscard]] std::optional<AzEl> fixed_target() const;

  [[nodiscard]] Mode mode() const { return mode_; }
  [[nodiscard]] const std::string& who() const { return who_; }

  [[nodiscard]] const std::array<ParkSlot, kParkSlots>& park_slots() const { return slots_; }
  /// New slot positions (the console's parking editor). A station parked in a slot that moved
  /// goes to the new position.
  void set_park_slots(const std::array<ParkSlot, kParkSlots>& slots);

  /// The demand for this tick. `sky` is the tracked target's position (TRACK mode only).
  [[nodiscard]] Demand demand(const std::optional<AzEl>& sky) const;

 private:
  static Result<AzEl> checked(AzEl position);
  static Result<Jog> checked(Jog jog);
  void start_jog(Mode mode, Jog jog, std::string client, double now_s);

  std::array<ParkSlot, kParkSlots> slots_;
  OutOfRangePolicy policy_;
  double min_el_deg_;
  Mode mode_ = Mode::Stop;
  std::string who_ = "start-up";
  AzEl fixed_;  ///< MAN / PARK / EXT position
  int park_slot_ = 0;
  std::optional<Jog> jog_;         ///< EXT continuous move
  bool external_waiting_ = false;  ///< EXT allowed from the console, no program's position yet
  double jog_heard_s_ = 0.0;
  bool external_locked_ = false;
};

}  // namespace azt::control
