#include "azt/linux/hamlib_rotator.hpp"

#include <pthread.h>
#include <signal.h>

#include <cmath>
#include <exception>
#include <string_view>
#include <system_error>
#include <utility>

// Hamlib's C headers are not clean under -Wpedantic/-Wconversion; keep them out of our warnings.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <hamlib/rotator.h>
#pragma GCC diagnostic pop

#include "hamlib_process.hpp"

namespace azt::linux_os {
namespace {

using Clock = std::chrono::steady_clock;

Result<bool> set_conf(ROT* rot, const char* name, const std::string& value,
                      const std::string& model) {
  const token_t token = rot_token_lookup(rot, name);
  if (token == RIG_CONF_END) return fail(model + " has no setting '" + name + "'");
  const int rc = rot_set_conf(rot, token, value.c_str());
  if (rc != RIG_OK) {
    return fail("setting " + std::string(name) + "=" + value + " on " + model +
                " failed: " + hamlib_status_text(rc));
  }
  return true;
}

Result<bool> validate(const HamlibConfig& config) {
  if (config.model <= 0) return fail("Hamlib rotator model must be positive");
  if (config.baud < 0) return fail("baud must be 0 (backend default) or positive");
  if (!std::isfinite(config.poll_s) || config.poll_s < 0.01 || config.poll_s > 60.0) {
    return fail("poll_s must be within 0.01..60 s");
  }
  if (!std::isfinite(config.min_move_deg) || config.min_move_deg < 0.0) {
    return fail("min_move_deg must be finite and non-negative");
  }
  if (!std::isfinite(config.reconnect_s) || config.reconnect_s < 0.01 ||
      config.reconnect_s > 600.0) {
    return fail("reconnect_s must be within 0.01..600 s");
  }
  return true;
}

std::string text_or_unknown(const char* text) { return text != nullptr ? text : "?"; }

Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

}  // namespace

HamlibRotator::HamlibRotator(HamlibConfig config) : config_(std::move(config)) {}

Result<std::unique_ptr<HamlibRotator>> HamlibRotator::open(const HamlibConfig& config) {
  if (auto valid = validate(config); !valid) return valid.error();
  try {
    std::unique_ptr<HamlibRotator> rotator(new HamlibRotator(config));
    if (auto started = rotator->start_worker(); !started) return started.error();
    if (auto opened = rotator->await_first_open(); !opened) return opened.error();
    return rotator;
  } catch (const std::exception& e) {
    return fail(std::string("cannot start the Hamlib worker: ") + e.what());
  }
}

HamlibRotator::~HamlibRotator() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (worker_.joinable()) worker_.join();
}

Result<bool> HamlibRotator::start_worker() {
  // The worker blocks every signal: the daemon's handlers run on the event-loop thread, and a
  // write to a peer that has gone away (a killed rotctld) yields EPIPE instead of a SIGPIPE that
  // would kill the process. The mask is inherited at creation, so there is no window.
  sigset_t all;
  sigset_t previous;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &previous);
  std::string error;
  try {
    worker_ = std::thread([this] { run(); });
  } catch (const std::system_error& e) {
    error = e.what();
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (!error.empty()) return fail("cannot start the Hamlib worker thread: " + error);
  return true;
}

Result<bool> HamlibRotator::await_first_open() {
  std::unique_lock lock(mutex_);
  wake_.wait(lock, [this] { return open_state_ != OpenState::Opening; });
  if (open_state_ == OpenState::Failed) return fail(open_error_);
  return true;
}

void HamlibRotator::command_position(double az_deg, double el_deg) {
  {
    const std::lock_guard lock(mutex_);
    if (!std::isfinite(az_deg) || !std::isfinite(el_deg)) {
      last_error_ = "ignored a non-finite setpoint";
      return;
    }
    pending_ = Setpoint{az_deg, el_deg};
  }
  wake_.notify_all();
}

void HamlibRotator::command_stop() {
  {
    const std::lock_guard lock(mutex_);
    stop_pending_ = true;
    pending_.reset();
  }
  wake_.notify_all();
}

std::optional<HamlibRotator::Reading> HamlibRotator::latest() const {
  const std::lock_guard lock(mutex_);
  return latest_;
}

std::string HamlibRotator::last_error() const {
  const std::lock_guard lock(mutex_);
  return last_error_;
}

bool HamlibRotator::connected() const {
  const std::lock_guard lock(mutex_);
  return connected_;
}

// ---- worker thread ----------------------------------------------------------------------------

void HamlibRotator::run() {
  auto first = connect();
  {
    const std::lock_guard lock(mutex_);
    open_state_ = first.ok() ? OpenState::Open : OpenState::Failed;
    if (!first.ok()) open_error_ = first.error().message;
    connected_ = first.ok();
  }
  wake_.notify_all();
  if (!first.ok()) return;
  serve();
  if (rot_ != nullptr && connected()) rot_stop(rot_);  // leave the rotator still; result moot
  disconnect();
}

void HamlibRotator::serve() {
  next_poll_ = Clock::now();
  while (true) {
    if (rot_ == nullptr) {
      if (wait_for_shutdown(Clock::now() + seconds(config_.reconnect_s))) return;
      if (auto reopened = connect(); !reopened) {
        record_error("reconnect: " + reopened.error().message);
        continue;
      }
      last_sent_.reset();  // the box may have restarted: resend whatever is commanded next
      next_poll_ = Clock::now();
      const std::lock_guard lock(mutex_);
      connected_ = true;
    }
    Work work = take_work(next_poll_);
    if (work.exit) return;
    if (work.stop && !send_stop()) continue;
    if (work.position && !send_position(*work.position)) continue;
    if (Clock::now() >= next_poll_) {
      next_poll_ += seconds(config_.poll_s);
      if (next_poll_ < Clock::now()) next_poll_ = Clock::now();  // a slow box: don't burst
      poll_position();
    }
  }
}

Result<bool> HamlibRotator::connect() {
  ROT* rot = nullptr;
  {
    const std::lock_guard lock(hamlib_global_mutex());
    rig_set_debug(RIG_DEBUG_NONE);  // Hamlib prints its debug trail to stderr otherwise
    rot = rot_init(config_.model);
  }
  if (rot == nullptr) {
    return fail("Hamlib has no rotator model " + std::to_string(config_.model) +
                " (`rotctl -l` lists them)");
  }
  rot_ = rot;
  model_name_ = "model " + std::to_string(config_.model) + " (" +
                text_or_unknown(rot->caps->mfg_name) + " " +
                text_or_unknown(rot->caps->model_name) + ")";
  if (auto configured = configure(rot); !configured) {
    disconnect();
    return configured.error();
  }
  int rc = RIG_OK;
  {
    const std::lock_guard lock(hamlib_global_mutex());
    rc = rot_open(rot);
  }
  if (rc != RIG_OK) {
    disconnect();
    return fail("rot_open of " + describe() + " failed: " + hamlib_status_text(rc));
  }
  return true;
}

Result<bool> HamlibRotator::configure(ROT* rot) const {
  if (!config_.device.empty()) {
    if (auto set = set_conf(rot, "rot_pathname", config_.device, model_name_); !set) return set;
  }
  if (config_.baud > 0) {
    const std::string baud = std::to_string(config_.baud);
    if (auto set = set_conf(rot, "serial_speed", baud, model_name_); !set) return set;
  }
  return true;
}

/// Closes and frees the handle; rot_cleanup() closes an open port itself.
void HamlibRotator::disconnect() {
  if (rot_ == nullptr) return;
  {
    const std::lock_guard lock(hamlib_global_mutex());
    rot_cleanup(rot_);
  }
  rot_ = nullptr;
}

void HamlibRotator::drop_link(const std::string& error) {
  disconnect();
  const std::lock_guard lock(mutex_);
  connected_ = false;
  last_error_ = error;
}

bool HamlibRotator::wait_for_shutdown(Clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  return wake_.wait_until(lock, deadline, [this] { return stopping_; });
}

HamlibRotator::Work HamlibRotator::take_work(Clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  wake_.wait_until(lock, deadline,
                   [this] { return stopping_ || stop_pending_ || pending_.has_value(); });
  Work work;
  work.exit = stopping_;
  work.stop = std::exchange(stop_pending_, false);
  work.position = std::exchange(pending_, std::nullopt);
  return work;
}

/// Returns false when the link dropped; the stop stays pending for after the reconnect.
bool HamlibRotator::send_stop() {
  const int rc = rot_stop(rot_);
  last_sent_.reset();  // the same target may be commanded again after a stop
  if (rc == RIG_OK || !handle_failure(rc, "rot_stop")) return true;
  const std::lock_guard lock(mutex_);
  stop_pending_ = true;
  return false;
}

/// Returns false when the link dropped; the setpoint is kept unless something newer arrived.
bool HamlibRotator::send_position(const Setpoint& target) {
  if (last_sent_ && std::fabs(target.az_deg - last_sent_->az_deg) < config_.min_move_deg &&
      std::fabs(target.el_deg - last_sent_->el_deg) < config_.min_move_deg) {
    return true;
  }
  // Hamlib 4.5 carries angles as float (azimuth_t, elevation_t): ~1e-5 degree at 360.
  const int rc = rot_set_position(rot_, static_cast<azimuth_t>(target.az_deg),
                                  static_cast<elevation_t>(target.el_deg));
  if (rc == RIG_OK) {
    last_sent_ = target;
    return true;
  }
  if (!handle_failure(rc, "rot_set_position")) return true;
  const std::lock_guard lock(mutex_);
  if (!stop_pending_ && !pending_) pending_ = target;
  return false;
}

void HamlibRotator::poll_position() {
  azimuth_t az_deg = 0.0F;
  elevation_t el_deg = 0.0F;
  const Clock::time_point asked_at = Clock::now();
  const int rc = rot_get_position(rot_, &az_deg, &el_deg);
  if (rc != RIG_OK) {
    handle_failure(rc, "rot_get_position");
    return;
  }
  const std::lock_guard lock(mutex_);
  latest_ = Reading{static_cast<double>(az_deg), static_cast<double>(el_deg), asked_at};
}

/// Records a failed call; closes the handle on a link error. Returns true if the link dropped.
bool HamlibRotator::handle_failure(int rc, const std::string& what) {
  const std::string error = what + " on " + describe() + ": " + hamlib_status_text(rc);
  if (!is_hamlib_link_error(rc)) {
    record_error(error);
    return false;
  }
  drop_link(error);
  return true;
}

void HamlibRotator::record_error(const std::string& error) {
  const std::lock_guard lock(mutex_);
  last_error_ = error;
}

std::string HamlibRotator::describe() const {
  const std::string where = config_.device.empty() ? "its default port" : config_.device;
  return model_name_ + " at " + where;
}

}  // namespace azt::linux_os
