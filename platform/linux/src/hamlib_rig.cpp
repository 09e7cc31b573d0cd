// One rig through libhamlib on a worker thread (the rules are in azt/linux/hamlib_rig.hpp).
#include "azt/linux/hamlib_rig.hpp"

#include <pthread.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <utility>

// Hamlib's C headers are not clean under -Wpedantic/-Wconversion; keep them out of our warnings.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <hamlib/rig.h>
#pragma GCC diagnostic pop

#include "hamlib_process.hpp"

namespace azt::linux_os {
namespace {

using Clock = std::chrono::steady_clock;
using radio::RigCommand;
using radio::RigEvent;
using radio::RigEventKind;

Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

std::string text_or_unknown(const char* text) { return text != nullptr ? text : "?"; }

vfo_t tx_vfo(radio::SplitTxVfo vfo) {
  switch (vfo) {
    case radio::SplitTxVfo::VfoB:
      return RIG_VFO_B;
    case radio::SplitTxVfo::Sub:
      return RIG_VFO_SUB;
  }
  return RIG_VFO_B;
}

std::string where(const HamlibRigConfig& config) {
  return config.device.empty() ? "its default port" : config.device;
}

/// What became of one Hamlib call.
enum class Outcome { Done, Refused, Lost };

}  // namespace

/// The worker thread's side. The thread holds it too, so that a worker left to finish a slow call
/// after the owner is gone still has everything it touches; it then posts nothing.
struct HamlibRig::Worker {
  Worker(HamlibRigConfig c, HamlibRigOptions o, std::function<void(Report)> post)
      : config(std::move(c)), options(o), to_loop(std::move(post)) {}

  void run();

  // Set once.
  const HamlibRigConfig config;
  const HamlibRigOptions options;
  const std::function<void(Report)> to_loop;  ///< posts to the loop; only while !stopping

  // Shared with the loop, under `mutex`.
  std::mutex mutex;
  std::condition_variable wake;
  Requests pending;
  bool stopping = false;  ///< the owner is gone or going: nothing more is posted
  bool exited = false;

 private:
  struct Turn {
    bool stop = false;
    bool idle_check = false;
    Requests requests;
  };
  Result<bool> open();
  Result<bool> configure();
  void close();
  Turn take_turn();
  bool wait_for_stop(double s);
  bool carry_out(const Requests& r);
  bool write_split(double hz);
  bool read(bool split, bool report);
  Outcome check(int rc, RigCommand command, const char* call, bool report = true);
  void written(RigCommand command, double hz);
  void post(Report report);
  void post_opened();
  [[nodiscard]] std::string describe() const;

  // The worker thread's own.
  RIG* rig_ = nullptr;
  std::string model_name_;
  bool split_on_ = false;
  bool split_refused_ = false;
  unsigned open_attempts_ = 0;
  std::string lost_why_;
  Clock::time_point last_exchange_;
};

// ---- the loop's side ---------------------------------------------------------------------------

HamlibRig::HamlibRig(boost::asio::io_context& io, HamlibRigConfig config, HamlibRigOptions options,
                     RigLinkEvents events)
    : config_(std::move(config)), events_(std::move(events)) {
  worker_ = std::make_shared<Worker>(config_, options, [this, &io, alive = alive_](Report r) {
    boost::asio::post(io, [this, alive, r = std::move(r)] {
      if (*alive) on_report(r);
    });
  });
  // The worker blocks every signal: the daemon's handlers run on the loop's thread, and a write
  // to a peer gone away (model 2's rigctld killed) yields EPIPE, not a SIGPIPE that would end
  // the process. Threads Hamlib starts inherit the mask. std::thread throws when it cannot start
  // one: as any failure at start, that ends the daemon's start with its message.
  sigset_t all;
  sigset_t previous;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &previous);
  try {
    thread_ = std::thread([w = worker_] { w->run(); });
  } catch (...) {
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    throw;
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

HamlibRig::~HamlibRig() {
  *alive_ = false;
  std::unique_lock lock(worker_->mutex);
  worker_->stopping = true;
  worker_->wake.notify_all();
  const bool exited = worker_->wake.wait_for(lock, seconds(worker_->options.close_wait_s),
                                             [this] { return worker_->exited; });
  lock.unlock();
  if (exited) {
    thread_.join();
  } else {
    thread_.detach();  // inside a slow call: it closes the rig when that returns
  }
}

std::string HamlibRig::describe() const { return describe_hamlib_rig(config_); }

bool HamlibRig::set_rx_hz(double hz) {
  if (!up() || !radio::is_rig_frequency(hz)) return false;
  queued_.rx_hz = std::round(hz);
  return true;
}

bool HamlibRig::set_tx_hz(double hz) {
  if (!up() || split_refused_ || !radio::is_rig_frequency(hz)) return false;
  queued_.tx_hz = std::round(hz);
  return true;
}

bool HamlibRig::read_rx() {
  if (!up()) return false;
  queued_.read_rx = true;
  return true;
}

void HamlibRig::flush() {
  if (!queued_.any()) return;
  {
    const std::lock_guard lock(worker_->mutex);
    Requests& p = worker_->pending;
    if (queued_.rx_hz) p.rx_hz = queued_.rx_hz;  // a newer frequency replaces one not yet sent
    if (queued_.tx_hz) p.tx_hz = queued_.tx_hz;
    p.read_rx = p.read_rx || queued_.read_rx;
  }
  queued_ = Requests();
  worker_->wake.notify_all();
}

void HamlibRig::on_report(const Report& report) {
  open_attempts_ = std::max(open_attempts_, report.open_attempts);
  switch (report.kind) {
    case Report::Kind::Opened:
      state_ = RigLinkState::Up;
      down_reason_.clear();
      split_refused_ = false;
      down_reported_ = false;
      if (events_.link) events_.link(RigLinkState::Up, "");
      return;
    case Report::Kind::Lost:
      return on_lost(report.why);
    case Report::Kind::Answer:
      if (report.answer.kind == RigEventKind::Refused &&
          report.answer.command == RigCommand::SetSplit) {
        split_refused_ = true;  // no TX until the next connection, as rigctld's session does
      }
      if (events_.event) events_.event(report.answer);
      return;
  }
}

void HamlibRig::on_lost(const std::string& why) {
  const bool was_up = std::exchange(state_, RigLinkState::Down) == RigLinkState::Up;
  down_reason_ = why;
  queued_ = Requests();
  // Said once per loss: a rig that stays switched off is not news every retry.
  if (events_.link && (was_up || !down_reported_)) events_.link(RigLinkState::Down, why);
  down_reported_ = true;
}

// ---- the worker's side -------------------------------------------------------------------------

void HamlibRig::Worker::run() {
  double retry_s = options.retry_s;
  for (;;) {
    if (rig_ == nullptr) {
      if (auto opened = open(); !opened) {
        post(Report{Report::Kind::Lost, opened.error().message, {}, open_attempts_});
        if (wait_for_stop(retry_s)) break;
        retry_s = std::min(retry_s * 2.0, options.max_retry_s);
        continue;
      }
      retry_s = options.retry_s;
      post_opened();
    }
    const Turn turn = take_turn();
    if (turn.stop) break;
    const bool kept = turn.idle_check ? read(false, false) : carry_out(turn.requests);
    if (kept) continue;
    close();
    post(Report{Report::Kind::Lost, lost_why_, {}, open_attempts_});
    if (wait_for_stop(retry_s)) break;
  }
  close();
  const std::lock_guard lock(mutex);
  exited = true;
  wake.notify_all();
}

Result<bool> HamlibRig::Worker::open() {
  ++open_attempts_;
  RIG* r = nullptr;
  {
    const std::lock_guard lock(hamlib_global_mutex());
    rig_set_debug(RIG_DEBUG_NONE);  // Hamlib prints its debug trail to stderr otherwise
    r = rig_init(static_cast<rig_model_t>(config.model));
  }
  if (r == nullptr) {
    return fail("Hamlib has no rig model " + std::to_string(config.model) +
                " (`rigctl -l` lists them)");
  }
  rig_ = r;
  model_name_ = "model " + std::to_string(config.model) + " (" +
                text_or_unknown(r->caps->mfg_name) + " " + text_or_unknown(r->caps->model_name) +
                ")";
  if (auto configured = configure(); !configured) {
    close();
    return configured.error();
  }
  int rc = RIG_OK;
  {
    // rig_open enters the rig in Hamlib's list of open rigs: under the process lock, as the
    // rotator's rot_open is.
    const std::lock_guard lock(hamlib_global_mutex());
    rc = rig_open(rig_);
  }
  if (rc != RIG_OK) {
    close();
    return fail("rig_open of " + describe() + " failed: " + hamlib_status_text(rc));
  }
  // Many backends open a port whose rig is switched off (an Icom on a silent port: 9 s, then
  // RIG_OK). Up means the rig answers: a first read of the dial says so, or the link stays down
  // with one report instead of an up and a down every retry.
  freq_t hz = 0.0;
  if (const int probe = rig_get_freq(rig_, RIG_VFO_CURR, &hz); is_hamlib_link_error(probe)) {
    close();
    return fail(describe() + " does not answer: rig_get_freq: " + hamlib_status_text(probe));
  }
  split_on_ = false;
  split_refused_ = false;
  last_exchange_ = Clock::now();
  return true;
}

Result<bool> HamlibRig::Worker::configure() {
  const auto set = [this](const char* name, const std::string& value) -> Result<bool> {
    const token_t token = rig_token_lookup(rig_, name);
    if (token == RIG_CONF_END) return fail(model_name_ + " has no setting '" + name + "'");
    const int rc = rig_set_conf(rig_, token, value.c_str());
    if (rc != RIG_OK) {
      return fail("setting " + std::string(name) + "=" + value + " on " + model_name_ +
                  " failed: " + hamlib_status_text(rc));
    }
    return true;
  };
  if (!config.device.empty()) {
    if (auto done = set("rig_pathname", config.device); !done) return done;
  }
  if (config.baud > 0) return set("serial_speed", std::to_string(config.baud));
  return true;
}

/// Closes the port and frees the handle: rig_cleanup closes an open rig itself.
void HamlibRig::Worker::close() {
  if (rig_ == nullptr) return;
  {
    const std::lock_guard lock(hamlib_global_mutex());
    rig_cleanup(rig_);
  }
  rig_ = nullptr;
}

HamlibRig::Worker::Turn HamlibRig::Worker::take_turn() {
  std::unique_lock lock(mutex);
  const bool woken = wake.wait_until(lock, last_exchange_ + seconds(options.idle_check_s),
                                     [this] { return stopping || pending.any(); });
  Turn turn;
  turn.stop = stopping;
  turn.idle_check = !woken;
  turn.requests = std::exchange(pending, Requests());
  return turn;
}

bool HamlibRig::Worker::wait_for_stop(double s) {
  std::unique_lock lock(mutex);
  return wake.wait_for(lock, seconds(s), [this] { return stopping; });
}

/// One turn's requests, in the order rigctld's session sends them; false when the link was lost
/// (lost_why_ says why).
bool HamlibRig::Worker::carry_out(const Requests& r) {
  bool dial_read = false;
  if (r.rx_hz) {
    const Outcome set =
        check(rig_set_freq(rig_, RIG_VFO_CURR, *r.rx_hz), RigCommand::SetFreq, "rig_set_freq");
    if (set == Outcome::Lost) return false;
    if (set == Outcome::Done) {
      written(RigCommand::SetFreq, *r.rx_hz);
      if (!read(false, true)) return false;
      dial_read = true;  // the read back is the dial too
    }
  }
  if (r.tx_hz && !write_split(*r.tx_hz)) return false;
  if (r.read_rx && !dial_read) return read(false, true);
  return true;
}

bool HamlibRig::Worker::write_split(double hz) {
  if (!split_on_ && !split_refused_) {
    const Outcome on =
        check(rig_set_split_vfo(rig_, RIG_VFO_CURR, RIG_SPLIT_ON, tx_vfo(options.split_tx_vfo)),
              RigCommand::SetSplit, "rig_set_split_vfo");
    if (on == Outcome::Lost) return false;
    split_on_ = on == Outcome::Done;
    split_refused_ = on == Outcome::Refused;  // said once: no TX until the next connection
    if (split_on_) written(RigCommand::SetSplit, 0.0);
  }
  if (!split_on_) return true;
  const Outcome set = check(rig_set_split_freq(rig_, RIG_VFO_CURR, hz), RigCommand::SetSplitFreq,
                            "rig_set_split_freq");
  if (set == Outcome::Lost) return false;
  if (set == Outcome::Done) {
    written(RigCommand::SetSplitFreq, hz);
    return read(true, true);
  }
  return true;
}

/// Reads the main VFO or the split frequency; `report`: post it (the idle check does not).
bool HamlibRig::Worker::read(bool split, bool report) {
  freq_t hz = 0.0;
  const RigCommand command = split ? RigCommand::GetSplitFreq : RigCommand::GetFreq;
  const int rc =
      split ? rig_get_split_freq(rig_, RIG_VFO_CURR, &hz) : rig_get_freq(rig_, RIG_VFO_CURR, &hz);
  const Outcome got = check(rc, command, split ? "rig_get_split_freq" : "rig_get_freq", report);
  if (got != Outcome::Done) return got != Outcome::Lost;
  if (!radio::is_rig_frequency(hz)) {
    // Not a frequency: the rig's answers cannot be trusted, as rigctld's garbage fails its link.
    lost_why_ = std::string(split ? "rig_get_split_freq" : "rig_get_freq") + " on " + describe() +
                " answered " + std::to_string(hz) + " Hz";
    return false;
  }
  if (!report) return true;
  RigEvent e;
  e.kind = split ? RigEventKind::TxRead : RigEventKind::RxRead;
  e.command = command;
  e.hz = hz;
  post(Report{Report::Kind::Answer, "", e, open_attempts_});
  return true;
}

/// Sorts a call's status: done, refused (posted if `report`; the link stays up) or lost
/// (lost_why_).
Outcome HamlibRig::Worker::check(int rc, RigCommand command, const char* call, bool report) {
  last_exchange_ = Clock::now();
  if (rc == RIG_OK) return Outcome::Done;
  const std::string status = hamlib_status_text(rc);
  if (is_hamlib_link_error(rc)) {
    lost_why_ = std::string(call) + " on " + describe() + ": " + status;
    return Outcome::Lost;
  }
  if (!report) return Outcome::Refused;
  RigEvent e;
  e.kind = RigEventKind::Refused;
  e.command = command;
  e.rprt = rc;
  e.message = std::string(call) + ": " + status;
  post(Report{Report::Kind::Answer, "", e, open_attempts_});
  return Outcome::Refused;
}

void HamlibRig::Worker::written(RigCommand command, double hz) {
  RigEvent e;
  e.kind = RigEventKind::Written;
  e.command = command;
  e.hz = hz;
  post(Report{Report::Kind::Answer, "", e, open_attempts_});
}

void HamlibRig::Worker::post(Report report) {
  const std::lock_guard lock(mutex);
  if (!stopping) to_loop(std::move(report));
}

/// What was asked while the rig was down belongs to the last connection: the loop writes afresh
/// once it hears the rig is up.
void HamlibRig::Worker::post_opened() {
  const std::lock_guard lock(mutex);
  pending = Requests();
  if (!stopping) to_loop(Report{Report::Kind::Opened, "", {}, open_attempts_});
}

std::string HamlibRig::Worker::describe() const {
  return (model_name_.empty() ? "model " + std::to_string(config.model) : model_name_) + " at " +
         where(config);
}

}  // namespace azt::linux_os
