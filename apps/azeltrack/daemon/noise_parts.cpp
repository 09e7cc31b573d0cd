// The daemon's noise measurements (docs/calibration.md "Sun noise and the figure of merit"): the
// runner's demand and tick beside the pointing scan's (control_loop.cpp), and each finished
// measurement appended, stamped with UTC, to the noise log beside the configuration.
#include <spdlog/spdlog.h>

#include <utility>

#include "azt/astro/time_scales.hpp"
#include "azt/linux/append_file.hpp"
#include "daemon/station_daemon.hpp"

namespace azt::app {

std::unique_ptr<NoiseRunner> StationDaemon::make_noise_runner() {
  const calibration::PowerFeed* feed =
      config_.receiver.source == ReceiverConfig::Source::None ? nullptr : &receiver_->feed();
  return std::make_unique<NoiseRunner>(
      feed, [this](nlohmann::json record) { log_noise(std::move(record)); });
}

void StationDaemon::log_noise(nlohmann::json record) {
  record["utc"] = astro::format_iso8601_utc_unix(unix_now_s());
  const std::string line = record.dump();
  spdlog::info("noise measurement: {}", line);
  auto failure = std::make_shared<std::string>();
  off_loop()(
      [path = beside_config(kNoiseLogFile), line, failure] {
        if (auto ok = linux_os::append_line(path, line); !ok) *failure = ok.error().message;
      },
      [failure] {
        if (!failure->empty()) spdlog::warn("noise log: {}", *failure);
      });
}

std::optional<control::AzEl> StationDaemon::noise_aim(const std::optional<control::AzEl>& source) {
  if (!noise_->running()) return source;
  // The measurement ends with any other command (STOP, another target, a PC program), a fault,
  // or a pointing scan (which has the receiver and the aim then).
  const bool on_source = modes_.mode() == control::Mode::Track && sky_.target() &&
                         sky_.target()->name == noise_->source();
  if (!on_source) {
    noise_->stop("stopped: the station was given another command");
  } else if (!antenna_->faults().empty()) {
    noise_->stop("stopped: " + antenna_->faults().front());
  } else if (scanner_->running()) {
    noise_->stop("stopped: a pointing scan began");
  }
  if (!noise_->running() || !source) return source;
  return noise_->aim(*source);
}

void StationDaemon::noise_tick(double now, const std::optional<control::AzEl>& source) {
  if (!noise_->running()) return;
  const auto position = antenna_->position(now);
  noise_->tick(now, !position || position->moving, antenna_->encoder_reading(), source);
  if (!noise_->running()) {
    spdlog::info("noise measurement of {}: {}", noise_->source(),
                 noise_->to_json().value("state", ""));
    if (console_) console_->push_now();
  }
}

}  // namespace azt::app
