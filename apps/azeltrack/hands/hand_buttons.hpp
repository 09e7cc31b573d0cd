#pragma once
// The buttons at the mast (docs/hardware.md, "Buttons and a game pad"): CW, CCW, UP, DOWN, STOP
// and PARK on GPIO lines ([gpio] button_*), debounced (the core's DebouncedInput) and turned into
// the hands' commands (HandControl) through the front door (HandDoor) as the source "buttons".
// Read each control tick, and on every edge, so a press shorter than a tick is not lost to the
// debounce's clock.

#include <array>
#include <functional>
#include <memory>

#include "azt/hands/debounced_input.hpp"
#include "azt/hands/hand_control.hpp"
#include "azt/linux/gpio.hpp"
#include "config/daemon_config.hpp"
#include "hands/hand_door.hpp"

namespace azt::app {

class HandButtons {
 public:
  /// Requests the configured lines (pull-ups: a button to ground). A line it cannot have is a
  /// UsageError naming the key, as every [gpio] line's.
  HandButtons(const ButtonsConfig& config, linux_os::GpioProvider& gpio, StationCommands& commands,
              std::function<double()> monotonic_s);

  /// One control tick: what the buttons hold now, through the front door.
  void tick();
  [[nodiscard]] hands::HandInputs held() const;

 private:
  struct Button {
    std::unique_ptr<linux_os::GpioInput> line;  ///< null: not wired
    hands::DebouncedInput debounced{0.0};
  };
  enum Index : std::size_t { Cw, Ccw, Up, Down, Stop, Park, Count };

  void request(Button& button, const std::optional<linux_os::GpioLineSpec>& spec,
               linux_os::GpioProvider& gpio, double debounce_s);

  std::function<double()> monotonic_s_;
  std::array<Button, Count> buttons_;
  hands::HandControl control_;
  HandDoor door_;
};

}  // namespace azt::app
