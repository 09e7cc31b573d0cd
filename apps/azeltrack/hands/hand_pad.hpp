#pragma once
// A game pad or joystick at the mast (docs/hardware.md, "Buttons and a game pad"): its state read
// each control tick (platform/linux's EvdevPad keeps it from the input events), turned into the
// hands' commands (the core's pad_inputs and HandControl) and taken through the front door
// (HandDoor) as the source "game pad". The stick's deflection is the speed.
//
// A pad is unplugged and plugged in again at a mast: one that is absent at start or goes away is
// looked for again every kRetryS, and a pad that goes away lets go at once (the move stops as
// when the stick is released). Each new reason it cannot be had is logged once, not every retry.

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "azt/hands/hand_control.hpp"
#include "azt/hands/pad_state.hpp"
#include "azt/linux/evdev_pad.hpp"
#include "config/gamepad_config.hpp"
#include "hands/hand_door.hpp"

namespace azt::app {

class HandPad {
 public:
  static constexpr double kRetryS = 2.0;
  /// Opens the pad's device (open_evdev_pad in the daemon; recorded pads in tests).
  using Opener = std::function<Result<std::unique_ptr<linux_os::EvdevPad>>(const std::string&)>;

  HandPad(const GamepadConfig& config, Opener open, StationCommands& commands,
          std::function<double()> monotonic_s, std::function<void(const std::string&)> log);

  /// One control tick: look for the pad if due, then what it holds now through the front door.
  void tick();
  /// The pad's name while it is connected; empty otherwise.
  [[nodiscard]] std::string connected_name() const;
  /// For /api/state `station_io.gamepad` (docs/web-api.md): the configured device, whether the
  /// pad is connected and its name, or why it cannot be had (null while it is simply being looked
  /// for again after going away).
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  void look_for_pad(double now_s);
  [[nodiscard]] hands::HandInputs held() const;

  GamepadConfig config_;
  Opener open_;
  std::function<double()> monotonic_s_;
  std::function<void(const std::string&)> log_;
  std::unique_ptr<linux_os::EvdevPad> pad_;
  double next_look_s_ = 0.0;
  std::string last_error_;  ///< the last reason logged, so a retry's same reason is not
  hands::PadLayout layout_;
  hands::HandControl control_;
  HandDoor door_;
};

/// The daemon's pad on Linux input events (`io` watches its descriptor); nullptr without a
/// [gamepad] device. Opening a missing pad is no error: it is looked for every kRetryS.
std::unique_ptr<HandPad> make_hand_pad(boost::asio::io_context& io,
                                       const std::optional<GamepadConfig>& config,
                                       StationCommands& commands,
                                       std::function<double()> monotonic_s,
                                       std::function<void(const std::string&)> log);

}  // namespace azt::app
