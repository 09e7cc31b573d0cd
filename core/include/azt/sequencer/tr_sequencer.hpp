#pragma once
// The transmit/receive sequencer of seed 002: PTT keys a chain of outputs one step at a time —
// by default preamp isolation, T/R relay, amplifier, radio — and releases them in reverse order,
// so RF never meets a relay that is still moving or a preamp that is still connected.
//
// Pure and driven by injected time (milliseconds): call update() on every PTT edge and whenever
// next_deadline_ms() is reached; each transition is stamped with the exact instant it was due.
// Outputs are numbered in keying order; `true` is energized, and de-energized is the safe
// receive state (the wiring's job, as in the seed).
//
// Rules (reliability notes R17/R18):
//  * PTT is debounced: a level counts once it has been stable for debounce_ms.
//  * Keying: output 0 at once, then output k+1 no sooner than delays_ms[k] after output k.
//  * Releasing: the highest keyed output at once, then output k no sooner than delays_ms[k]
//    after output k+1. A release in the middle of keying releases what was keyed so far.
//  * A release runs to the end before keying starts again, so a bouncing PTT never reverses a
//    relay that is still travelling.
//  * The transmit time-out (always on) releases the chain tx_timeout_s after PTT went active and
//    latches until PTT is released.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "azt/util/result.hpp"

namespace azt::sequencer {

struct SequencerConfig {
  std::vector<std::string> outputs;  ///< keying order
  std::vector<double> delays_ms;  ///< delays_ms[k]: between output k and k+1 (size outputs − 1)
  double debounce_ms = 10.0;
  double tx_timeout_s = 600.0;
  bool hold_motion = true;  ///< no antenna motion while any output is energized

  static constexpr std::size_t kMaxOutputs = 8;
  static constexpr double kMaxDelayMs = 2000.0;
  static constexpr double kMaxDebounceMs = 200.0;
  static constexpr double kMaxTimeoutS = 3600.0;

  /// Validates: 1–8 distinct non-empty names; one delay per gap, each 1–2000 ms; debounce
  /// 0–200 ms; time-out 1 s – 1 h (it cannot be switched off: R18).
  static Result<SequencerConfig> make(std::vector<std::string> outputs,
                                      std::vector<double> delays_ms, double debounce_ms,
                                      double tx_timeout_s, bool hold_motion);
  /// The seed's chain: preamp, trx_relay, amplifier, radio, 20 ms apart.
  static SequencerConfig seed_default();
};

struct Transition {
  double t_ms = 0.0;
  std::size_t line = 0;  ///< index into SequencerConfig::outputs
  bool on = false;
};

class TrSequencer {
 public:
  explicit TrSequencer(SequencerConfig config);

  /// The PTT input at `t_ms` (true: transmit requested; the Linux side inverts an active-low
  /// line). Runs every step due up to `t_ms` first, then takes the input. `t_ms` must not go back.
  std::vector<Transition> update(double t_ms, bool ptt);
  /// When update() must be called next even without an input edge (nullopt: nothing pending).
  [[nodiscard]] std::optional<double> next_deadline_ms() const;

  [[nodiscard]] const std::vector<bool>& outputs() const { return outputs_; }
  [[nodiscard]] const SequencerConfig& config() const { return config_; }
  /// Every output energized: the radio may transmit.
  [[nodiscard]] bool transmitting() const { return level_ == outputs_.size(); }
  [[nodiscard]] bool timed_out() const { return latched_; }
  /// Antenna motion must wait (hold_motion and any output energized, or PTT held).
  [[nodiscard]] bool motion_hold() const;

 private:
  [[nodiscard]] std::size_t wanted_level() const;
  [[nodiscard]] std::optional<double> step_deadline() const;
  void advance(double t_ms, std::vector<Transition>& out);

  SequencerConfig config_;
  std::vector<bool> outputs_;
  std::size_t level_ = 0;  ///< outputs 0..level_-1 are energized
  bool raw_ptt_ = false;
  double raw_since_ms_ = 0.0;
  bool ptt_ = false;  ///< debounced
  double ptt_since_ms_ = 0.0;
  bool latched_ = false;
  bool releasing_ = false;  ///< the last transition was a release
  std::optional<double> last_step_ms_;
  double now_ms_ = 0.0;
};

}  // namespace azt::sequencer
