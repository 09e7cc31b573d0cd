#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

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

/// Where the antenna should point now, and why.
struct Demand {
  std::optional<AzEl> position;  ///< nullopt: do not move (STOP, or holding)
  std::string reason;            ///< for the status line: "tracking Moon", "holding: Moon set"
};

/// Which mode is active and what it asks for. Pure: the tracker feeds it the sky position of the
/// tracked target each tick; it never computes astronomy itself.
class ModeController {
 public:
  static constexpr int kParkSlots = 4;

  ModeController(std::array<ParkSlot, kParkSlots> slots, OutOfRangePolicy policy, double min_el_deg)
      : slots_(std::move(slots)), policy_(policy), min_el_deg_(min_el_deg) {}

  void track(std::string target_name);
  Result<Mode> manual(AzEl position);
  Result<Mode> park(int slot);  ///< 1..4
  Result<Mode> external(AzEl position, std::string client);
  void stop();

  [[nodiscard]] Mode mode() const { return mode_; }
  [[nodiscard]] const std::string& who() const { return who_; }

  /// The demand for this tick. `sky` is the tracked target's position (TRACK mode only).
  [[nodiscard]] Demand demand(const std::optional<AzEl>& sky) const;

 private:
  static Result<AzEl> checked(AzEl position);

  std::array<ParkSlot, kParkSlots> slots_;
  OutOfRangePolicy policy_;
  double min_el_deg_;
  Mode mode_ = Mode::Stop;
  std::string who_ = "start-up";
  AzEl fixed_;  ///< MAN / PARK / EXT position
  int park_slot_ = 0;
};

}  // namespace azt::control
