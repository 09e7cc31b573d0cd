// The daemon's control loop: one thread, one Asio loop (docs/daemon.md). The tick runs on a timer
// re-armed at absolute deadlines; SIGINT, SIGTERM and SIGHUP stop the motors and leave cleanly; an
// exception that escapes a handler stops the motors and releases the transmitter before exit 1.
#include <spdlog/spdlog.h>

#include <memory>

#include "azt/linux/crash_safe_outputs.hpp"
#include "azt/linux/self_restart.hpp"
#include "common/usage_error.hpp"
#include "daemon/station_daemon.hpp"

namespace azt::app {

namespace asio = boost::asio;

StationDaemon::~StationDaemon() {
  // Members are destroyed after this body, in reverse order; the workers' jobs finish first (a
  // download under way is abandoned rather than waited for).
  downloads_cancelled_ = true;
  download_worker_.finish();
  worker_.finish();
  status_worker_.finish();
}

int StationDaemon::run() {
  linux_os::install_crash_handlers();
  elements_->start(unix_now_s());  // at once: the start target may be a satellite
  start_target();
  resume_calibration();
  open_servers();
  signals_.async_wait([this](boost::system::error_code ec, int signal) {
    if (!ec) {
      shutdown(signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "SIGHUP");
    }
  });
  if (options_.run_for_s > 0.0) {
    auto stop_timer = std::make_shared<asio::steady_timer>(io_);
    stop_timer->expires_after(std::chrono::duration_cast<SteadyClock::duration>(
        std::chrono::duration<double>(options_.run_for_s)));
    stop_timer->async_wait([this, stop_timer](boost::system::error_code ec) {
      if (!ec) shutdown("--run-for elapsed");
    });
  }
  deadline_ = SteadyClock::now() + period_;
  arm_tick();
  spdlog::info("serving {} with {}; tick {:.0f} Hz", options_.config_path, antenna_->describe(),
               1.0 / config_.station.tick_s);
  notifier_.ready("tracking " + modes_.who());
  if (options_.on_loop_started) asio::post(io_, [this] { options_.on_loop_started(io_); });
  try {
    io_.run();
  } catch (const std::exception& e) {
    fail_safe(std::string("internal error: ") + e.what());
    return kExitFailure;
  } catch (...) {
    fail_safe("internal error (not a std::exception)");
    return kExitFailure;
  }
  spdlog::info("stopped; tick {}", stats_.summary());
  return restart_requested_ ? linux_os::kExitRestart : 0;
}

void StationDaemon::restart_soon(const std::string& who) {
  // After the answer has gone out: the console that asked hears "restarting" before the
  // servers close.
  auto timer = std::make_shared<asio::steady_timer>(io_, std::chrono::milliseconds(300));
  timer->async_wait([this, timer, who](boost::system::error_code ec) {
    if (!ec) restart(who);
  });
}

void StationDaemon::restart(const std::string& who) {
  // The same way out as a signal: motors stopped and outputs released before anything closes.
  restart_requested_ = true;
  shutdown("restart asked by " + who);
}

void StationDaemon::arm_tick() {
  timer_.expires_at(deadline_);
  timer_.async_wait([this](boost::system::error_code ec) {
    if (ec || stopping_) return;
    const auto woke = SteadyClock::now();
    stats_.add(std::chrono::duration<double>(woke - deadline_).count());
    tick();
    // Absolute deadlines: a late tick does not delay the next one. After a stall longer than
    // a period (suspend, debugger) skip ahead instead of running a burst of ticks.
    deadline_ += period_;
    if (SteadyClock::now() > deadline_) {
      stats_.overrun();
      deadline_ = SteadyClock::now() + period_;
    }
    arm_tick();
  });
}

void StationDaemon::tick() {
  const double now = now_s();
  if (buttons_) buttons_->tick();
  if (pad_) pad_->tick();
  modes_.update(now);
  elements_->tick(unix_now_s());
  satellites_.refresh_passes(unix_now_s());
  schedule_->tick();
  pol_tick();
  if (commands_.tracking_satellite()) {
    control::AzEl rate;
    const control::Demand demand = satellites_.demand(unix_now_s(), mount_az(), rate);
    antenna_->tick(now, demand, rate);
    recording_tick(now, demand);
  } else {
    std::optional<SkyFix> fix;
    if (modes_.mode() == control::Mode::Track) {
      fix = sky_.at(unix_now_s());
    }
    const std::optional<control::AzEl> source = fix ? std::optional(fix->position) : std::nullopt;
    control::Demand demand = modes_.demand(noise_aim(scan_aim(source)));
    if (auto test = direction_test_.demand(now)) demand = std::move(*test);
    if (auto pol_test = direction_test_.pol_demand(now)) antenna_->set_pol_demand(*pol_test);
    antenna_->tick(now, demand, fix ? fix->rate_deg_s : control::AzEl{});
    direction_test_.tick(now);
    receiver_->tick(now);
    scan_tick(now, source);
    noise_tick(now, source);
    recording_tick(now, demand);
    calibration_tick(now);
  }
  report_faults();
  // Mode changes by PC programs and new faults reach open consoles at once.
  std::string summary = std::string(control::to_string(modes_.mode())) + " " + modes_.who() + " " +
                        std::to_string(last_faults_.size());
  if (summary != last_summary_) {
    last_summary_ = std::move(summary);
    if (console_) console_->push_now();
  }
  notifier_.watchdog();
}

std::optional<control::AzEl> StationDaemon::scan_aim(const std::optional<control::AzEl>& source) {
  if (!scanner_->running()) return source;
  // The scan ends with any other command (STOP, another target, a PC program) or a fault.
  const bool on_source = modes_.mode() == control::Mode::Track && sky_.target() &&
                         sky_.target()->name == scanner_->source();
  if (!on_source) {
    scanner_->stop("stopped: the station was given another command");
  } else if (!antenna_->faults().empty()) {
    scanner_->stop("stopped: " + antenna_->faults().front());
  }
  if (!scanner_->running() || !source) return source;
  return scanner_->aim(*source);
}

void StationDaemon::scan_tick(double now, const std::optional<control::AzEl>& source) {
  if (!scanner_->running()) return;
  const auto position = antenna_->position(now);
  std::optional<control::AzEl> believed;
  if (position) believed = control::AzEl{position->az_deg, position->el_deg};
  scanner_->tick(now, !position || position->moving, antenna_->encoder_reading(), source, believed);
  if (!scanner_->running()) {
    spdlog::info("scan of {}: {}", scanner_->source(), scanner_->to_json().value("state", ""));
    if (console_) console_->push_now();
  }
}

void StationDaemon::report_faults() {
  const auto faults = antenna_->faults();
  if (faults != last_faults_) {
    for (const auto& f : faults) spdlog::warn("fault: {}", f);
    if (faults.empty() && !last_faults_.empty()) spdlog::info("faults cleared");
    last_faults_ = faults;
  }
}

void StationDaemon::fail_safe(const std::string& why) {
  stopping_ = true;
  antenna_->stop_now(now_s());
  sequencer_->release_now();
  spdlog::critical("{}: motors stopped, transmitter released, exiting", why);
  notifier_.stopping();
}

void StationDaemon::shutdown(const std::string& why) {
  if (stopping_) return;
  stopping_ = true;
  notifier_.stopping();
  // Motors first, then the servers: nothing may move after this line.
  antenna_->stop_now(now_s());
  sequencer_->release_now();
  recorder_->stop("the daemon stopped");  // its last rows go to the worker, which finishes them
  spdlog::info("{}: motors stopped, shutting down", why);
  if (rotctld_) rotctld_->close();
  for (auto& s : serial_) s->close();
  if (pstrotator_) pstrotator_->close();
  if (radio_) radio_->close();
  if (console_) console_->close();
  boost::system::error_code ignored;
  timer_.cancel();
  signals_.cancel(ignored);
  io_.stop();
}

int run_daemon(ConfigStore& store, const DaemonOptions& options) {
  StationDaemon daemon(store, options);
  return daemon.run();
}

}  // namespace azt::app
