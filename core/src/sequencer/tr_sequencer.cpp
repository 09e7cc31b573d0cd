#include "azt/sequencer/tr_sequencer.hpp"

#include <algorithm>
#include <cmath>

namespace azt::sequencer {

Result<SequencerConfig> SequencerConfig::make(std::vector<std::string> outputs,
                                              std::vector<double> delays_ms, double debounce_ms,
                                              double tx_timeout_s, bool hold_motion) {
  if (outputs.empty() || outputs.size() > kMaxOutputs) return fail("outputs: 1 to 8 lines");
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].empty()) return fail("outputs: a line needs a name");
    if (std::find(outputs.begin(), outputs.begin() + static_cast<std::ptrdiff_t>(i), outputs[i]) !=
        outputs.begin() + static_cast<std::ptrdiff_t>(i)) {
      return fail("outputs: '" + outputs[i] + "' appears twice");
    }
  }
  if (delays_ms.size() != outputs.size() - 1) {
    return fail("delays_ms: one delay between each pair of outputs (" +
                std::to_string(outputs.size() - 1) + ")");
  }
  for (const double d : delays_ms) {
    if (!std::isfinite(d) || d < 1.0 || d > kMaxDelayMs) return fail("delays: 1 to 2000 ms each");
  }
  if (!std::isfinite(debounce_ms) || debounce_ms < 0.0 || debounce_ms > kMaxDebounceMs) {
    return fail("debounce_ms: 0 to 200");
  }
  if (!std::isfinite(tx_timeout_s) || tx_timeout_s < 1.0 || tx_timeout_s > kMaxTimeoutS) {
    return fail("tx_timeout_s: 1 to 3600 (the time-out cannot be switched off)");
  }
  return SequencerConfig{std::move(outputs), std::move(delays_ms), debounce_ms, tx_timeout_s,
                         hold_motion};
}

SequencerConfig SequencerConfig::seed_default() {
  return *make({"preamp", "trx_relay", "amplifier", "radio"}, {20.0, 20.0, 20.0}, 10.0, 600.0,
               true);
}

TrSequencer::TrSequencer(SequencerConfig config)
    : config_(std::move(config)), outputs_(config_.outputs.size(), false) {}

bool TrSequencer::motion_hold() const { return config_.hold_motion && (level_ > 0 || ptt_); }

std::size_t TrSequencer::wanted_level() const {
  if (releasing_ && level_ > 0) return 0;  // finish a release before keying again
  return ptt_ && !latched_ ? outputs_.size() : 0;
}

std::optional<double> TrSequencer::step_deadline() const {
  const std::size_t want = wanted_level();
  if (want == level_) return std::nullopt;
  const bool keying = want > level_;
  // A change of direction, or the first step, is at once; a step in the same direction waits
  // the delay between the two outputs it separates.
  if (!last_step_ms_ || keying == releasing_ || (keying && level_ == 0)) return now_ms_;
  // Keying output `level_` follows output level_-1; releasing output level_-1 follows output
  // level_: either way the gap between outputs level_-1 and level_.
  return *last_step_ms_ + config_.delays_ms[level_ - 1];
}

std::optional<double> TrSequencer::next_deadline_ms() const {
  std::optional<double> next;
  const auto consider = [&next](double t) { next = next ? std::min(*next, t) : t; };
  if (raw_ptt_ != ptt_) consider(raw_since_ms_ + config_.debounce_ms);
  if (ptt_ && !latched_) consider(ptt_since_ms_ + config_.tx_timeout_s * 1000.0);
  if (const auto step = step_deadline()) consider(std::max(*step, now_ms_));
  return next;
}

void TrSequencer::advance(double t_ms, std::vector<Transition>& out) {
  now_ms_ = t_ms;
  if (raw_ptt_ != ptt_ && t_ms >= raw_since_ms_ + config_.debounce_ms) {
    ptt_ = raw_ptt_;
    ptt_since_ms_ = t_ms;
    if (!ptt_) latched_ = false;  // the time-out holds until PTT is released
  }
  if (ptt_ && !latched_ && t_ms >= ptt_since_ms_ + config_.tx_timeout_s * 1000.0) latched_ = true;
  const auto step = step_deadline();
  if (!step || *step > t_ms) return;
  const bool keying = wanted_level() > level_;
  const std::size_t line = keying ? level_ : level_ - 1;
  outputs_[line] = keying;
  level_ = keying ? level_ + 1 : level_ - 1;
  releasing_ = !keying;
  last_step_ms_ = t_ms;
  out.push_back(Transition{t_ms, line, keying});
}

std::vector<Transition> TrSequencer::update(double t_ms, bool ptt) {
  std::vector<Transition> out;
  // Everything due before this instant happens first, each at its own deadline. Every advance()
  // consumes the deadline it was called for, so the loops end; the cap is a guard, not a rule.
  constexpr int kMaxSteps = 10000;
  int steps = 0;
  for (auto due = next_deadline_ms(); due && *due < t_ms && steps < kMaxSteps;
       due = next_deadline_ms(), ++steps) {
    advance(*due, out);
  }
  now_ms_ = std::max(now_ms_, t_ms);
  if (ptt != raw_ptt_) {
    raw_ptt_ = ptt;
    raw_since_ms_ = t_ms;
  }
  for (auto due = next_deadline_ms(); due && *due <= t_ms && steps < kMaxSteps;
       due = next_deadline_ms(), ++steps) {
    advance(t_ms, out);
  }
  return out;
}

}  // namespace azt::sequencer
