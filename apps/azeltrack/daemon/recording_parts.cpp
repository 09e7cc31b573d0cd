// The daemon's recording (docs/calibration.md "Recording"): each control tick the recorder may take
// a row of the demand, the reading and the receiver's power; its batches are appended to
// recordings/ in the state directory on the worker thread, never on the loop.
#include <spdlog/spdlog.h>

#include <utility>

#include "calibration/recording_files.hpp"
#include "daemon/station_daemon.hpp"

namespace azt::app {

std::unique_ptr<Recorder> StationDaemon::make_recorder() {
  return std::make_unique<Recorder>([this](const std::string& name, std::string text, bool first) {
    auto failure = std::make_shared<std::string>();
    off_loop()(
        [dir = beside_config(kRecordingsDir), name, text = std::move(text), first, failure] {
          if (auto ok = append_recording(dir, name, text, first); !ok) {
            *failure = ok.error().message;
          }
        },
        [this, name, failure] {
          if (failure->empty()) return;
          spdlog::warn("recording {}: {}", name, *failure);
          recorder_->write_failed(name, *failure);
          if (console_) console_->push_now();
        });
  });
}

void StationDaemon::recording_tick(double now, const control::Demand& demand) {
  if (!recorder_->running()) return;
  RecordingSample sample;
  sample.unix_s = unix_now_s();
  sample.demand = demand.position;
  if (const auto here = antenna_->position(now)) {
    sample.reading = control::AzEl{here->az_deg, here->el_deg};
  }
  // The newest reading still fresh, without counting a silence as missing (a scan's business).
  if (config_.receiver.source != ReceiverConfig::Source::None) {
    const auto& feed = receiver_->feed();
    const auto recent = feed.readings_since(now - feed.settings().stale_s);
    if (!recent.empty()) sample.power_db = recent.back().power_db;
  }
  sample.mode = std::string(control::to_string(modes_.mode()));
  recorder_->sample(now, sample);
  if (!recorder_->running()) {
    spdlog::info("recording {}: {}", recorder_->to_json().value("file", ""),
                 recorder_->to_json().value("reason", ""));
    if (console_) console_->push_now();
  }
}

}  // namespace azt::app
