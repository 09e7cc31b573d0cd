#include "station/sequencer_runner.hpp"

#include <algorithm>
#include <chrono>

#include "azt/linux/asio.hpp"

namespace azt::app {

struct SequencerRunner::Timer {
  explicit Timer(boost::asio::io_context& io) : timer(io) {}
  boost::asio::steady_timer timer;
};

SequencerRunner::SequencerRunner(boost::asio::io_context& io, sequencer::SequencerConfig config,
                                 std::vector<std::unique_ptr<linux_os::GpioOutput>> outputs,
                                 std::function<double()> now_s,
                                 std::function<void(const std::string&)> log)
    : timer_(std::make_unique<Timer>(io)),
      sequencer_(std::move(config)),
      outputs_(std::move(outputs)),
      now_s_(std::move(now_s)),
      log_(std::move(log)) {}

SequencerRunner::~SequencerRunner() { release_now(); }

void SequencerRunner::release_now() {
  // Leaving: de-energize from the top of the chain down (the daemon's exit has no time for the
  // step delays, but this order is still the least harmful one: the PA's key goes first).
  inhibit_ = true;
  if (timer_) timer_->timer.cancel();
  for (auto it = outputs_.rbegin(); it != outputs_.rend(); ++it) (void)(*it)->set(false);
}

void SequencerRunner::set_ptt(bool pressed) {
  ptt_ = pressed;
  run();
}

void SequencerRunner::set_inhibit(bool inhibit) {
  inhibit_ = inhibit;
  run();
}

void SequencerRunner::clear_fault() {
  if (fault_.empty()) return;
  fault_.clear();
  run();
}

bool SequencerRunner::motion_hold() const { return sequencer_.motion_hold(); }

bool SequencerRunner::transmitting() const { return sequencer_.transmitting(); }

double SequencerRunner::core_now_ms() {
  const double real_ms = now_s_() * 1000.0;
  // Idle (nothing pending, nothing energized): the core may catch up with the real clock.
  const auto& on = sequencer_.outputs();
  if (!sequencer_.next_deadline_ms() && std::find(on.begin(), on.end(), true) == on.end()) {
    lag_ms_ = 0.0;
  }
  return std::max(real_ms - lag_ms_, last_core_ms_);
}

void SequencerRunner::run() { run_at(core_now_ms()); }

void SequencerRunner::run_at(double now_ms) {
  last_core_ms_ = now_ms;
  const bool request = ptt_ && !inhibit_ && fault_.empty();
  for (const sequencer::Transition& t : sequencer_.update(now_ms, request)) {
    const std::string& name = sequencer_.config().outputs[t.line];
    if (t.line < outputs_.size()) {
      if (auto r = outputs_[t.line]->set(t.on); !r && fault_.empty()) {
        fault_ = "sequencer: " + r.error().message;
        log_(fault_ + "; releasing the chain");
      }
    }
    log_("sequencer: " + name + (t.on ? " on" : " off"));
  }
  if (sequencer_.timed_out() && !was_timed_out_) {
    log_("sequencer: transmit time-out; released until PTT is let go");
  }
  was_timed_out_ = sequencer_.timed_out();
  // A write failure found above releases the chain from now on.
  if (!fault_.empty() && request) {
    run_at(now_ms);
    return;
  }
  arm();
}

void SequencerRunner::arm() {
  const auto due_ms = sequencer_.next_deadline_ms();
  timer_->timer.cancel();
  if (!due_ms) return;
  const double wait_s = std::max(0.0, (*due_ms + lag_ms_) / 1000.0 - now_s_());
  timer_->timer.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(wait_s)));
  timer_->timer.async_wait([this, due = *due_ms](boost::system::error_code ec) {
    if (ec) return;
    // A late wake-up must not shorten the next gap: the core is told it is the instant the step
    // was due, and its clock falls behind the real one by the lateness, so every later step is
    // due a full delay after this write, not after when it should have happened.
    const double real_core_ms = now_s_() * 1000.0 - lag_ms_;
    if (real_core_ms > due) lag_ms_ += real_core_ms - due;
    run_at(std::max(due, last_core_ms_));
  });
}

nlohmann::json SequencerRunner::state() const {
  nlohmann::json outputs = nlohmann::json::array();
  for (std::size_t i = 0; i < sequencer_.outputs().size(); ++i) {
    outputs.push_back({{"name", sequencer_.config().outputs[i]},
                       {"on", static_cast<bool>(sequencer_.outputs()[i])}});
  }
  return {{"wired", !outputs_.empty()},
          {"ptt", ptt_},
          {"inhibited", inhibit_ || !fault_.empty()},
          {"transmitting", sequencer_.transmitting()},
          {"timed_out", sequencer_.timed_out()},
          {"hold", sequencer_.motion_hold()},
          {"outputs", outputs}};
}

}  // namespace azt::app
