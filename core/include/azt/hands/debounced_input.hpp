#pragma once
// A push button or switch read through a GPIO line: its contacts bounce for milliseconds after
// each press and release, so a raw level is believed only once it has held for a settling time
// (K3NG's button handling waits the same way; docs/hardware.md, "Buttons and a game pad").

namespace azt::hands {

class DebouncedInput {
 public:
  /// `settle_s`: how long a new raw level must hold before it is the input's level (0: at once).
  explicit DebouncedInput(double settle_s) : settle_s_(settle_s) {}

  /// The raw level seen at `now_s` (an edge as it arrives, or a poll each control tick). Returns
  /// the debounced level.
  bool update(double now_s, bool raw);
  [[nodiscard]] bool level() const { return level_; }

 private:
  double settle_s_;
  bool raw_ = false;
  double raw_since_s_ = 0.0;
  bool level_ = false;
};

}  // namespace azt::hands
