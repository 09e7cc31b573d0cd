#pragma once
// The T/R sequencer (core/sequencer) on the daemon's event loop: PTT edges from a GPIO input,
// its steps on a timer at the exact instants the core asks for, outputs on GPIO lines.
//
// Safety: an output that cannot be written (a lost GPIO chip) latches a fault and the chain is
// released as if PTT had been let go; so does the E-stop (inhibit). Releasing keeps the core's
// reverse order and delays: the amplifier always drops before the T/R relay moves.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/linux/gpio.hpp"
#include "azt/sequencer/tr_sequencer.hpp"

namespace boost::asio {
class io_context;
}  // namespace boost::asio

namespace azt::app {

class SequencerRunner {
 public:
  /// `outputs`: one line per configured output in keying order, or none (the chain then runs in
  /// memory only, visible in the API). `now_s`: the daemon's monotonic clock.
  SequencerRunner(boost::asio::io_context& io, sequencer::SequencerConfig config,
                  std::vector<std::unique_ptr<linux_os::GpioOutput>> outputs,
                  std::function<double()> now_s, std::function<void(const std::string&)> log);
  ~SequencerRunner();
  SequencerRunner(const SequencerRunner&) = delete;
  SequencerRunner& operator=(const SequencerRunner&) = delete;
  SequencerRunner(SequencerRunner&&) = delete;
  SequencerRunner& operator=(SequencerRunner&&) = delete;

  /// The PTT input's level (true: transmit requested), raw: the core debounces it.
  void set_ptt(bool pressed);
  /// While inhibited (E-stop latched) PTT counts as released.
  void set_inhibit(bool inhibit);
  /// Every output off now, top of the chain first, without the step delays, and inhibited from
  /// then on: for the daemon's exit paths (a stop signal, an internal error).
  void release_now();
  /// Clears a latched output fault; the inhibit it caused lifts with it.
  void clear_fault();

  /// Antenna motion must wait ([sequencer] hold_motion and any output energized).
  [[nodiscard]] bool motion_hold() const;
  /// The transmitter keyed (the chain's last step on).
  [[nodiscard]] bool transmitting() const;
  [[nodiscard]] const std::string& fault() const { return fault_; }
  [[nodiscard]] const sequencer::TrSequencer& core() const { return sequencer_; }
  /// {"wired", "ptt", "inhibited", "transmitting", "timed_out", "hold", "outputs": [{"name","on"}]}
  [[nodiscard]] nlohmann::json state() const;

 private:
  void run();
  void run_at(double core_ms);
  void arm();
  /// The core's clock: the real one minus the accumulated lateness of timer wake-ups.
  double core_now_ms();

  struct Timer;
  std::unique_ptr<Timer> timer_;
  sequencer::TrSequencer sequencer_;
  std::vector<std::unique_ptr<linux_os::GpioOutput>> outputs_;
  std::function<double()> now_s_;
  std::function<void(const std::string&)> log_;
  bool ptt_ = false;
  bool inhibit_ = false;
  std::string fault_;
  bool was_timed_out_ = false;
  double lag_ms_ = 0.0;
  double last_core_ms_ = 0.0;
};

}  // namespace azt::app
