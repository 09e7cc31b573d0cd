#pragma once
// What the hands ask (the core's HandControl, azt/hands/hand_control.hpp), taken to the station's
// one front door (StationCommands) with the same rules as every other source: a latched fault
// refuses a move, the travel and the limit switches bound it, a keyed transmitter holds it.
//
// A held button asks the door once and then only renews the move's keep-alive each tick; a
// refused press is not asked again until the hands let go, so a button held through an E-stop
// leaves one refusal in the record, not twenty a second.

#include <optional>

#include "azt/control/modes.hpp"
#include "azt/hands/hand_control.hpp"
#include "station/station_commands.hpp"

namespace azt::app {

class HandDoor {
 public:
  /// `park_slot`: the slot the PARK button parks in (1…4).
  HandDoor(StationCommands& commands, CommandSource source, int park_slot)
      : commands_(commands), source_(std::move(source)), park_slot_(park_slot) {}

  void apply(const hands::HandAction& action);
  [[nodiscard]] const CommandSource& source() const { return source_; }

 private:
  void move(const control::Jog& jog);
  void forget();

  StationCommands& commands_;
  CommandSource source_;
  int park_slot_;
  std::optional<control::Jog> moving_;  ///< the move the door last accepted from these hands
  bool refused_ = false;                ///< this press was refused: not asked again until let go
};

/// The front door's continuous move for `action`'s speeds, each rounded to 5 % so that a stick's
/// jitter does not make a new command every tick.
control::Jog jog_of(const hands::HandAction& action);

}  // namespace azt::app
