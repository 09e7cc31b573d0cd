#include "calibration/recorder.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "azt/astro/time_scales.hpp"

namespace azt::app {
namespace {

/// A number to `decimals` places, or nothing (an empty CSV field) when unknown.
std::string field(std::optional<double> v, int decimals) {
  if (!v || !std::isfinite(*v)) return "";
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, *v);
  return text;
}

std::string csv_row(const RecordingSample& s) {
  std::optional<double> err_az;
  std::optional<double> err_el;
  if (s.demand && s.reading) {
    err_az = std::remainder(s.demand->az_deg - s.reading->az_deg, 360.0);
    err_el = s.demand->el_deg - s.reading->el_deg;
  }
  auto az = [](const std::optional<control::AzEl>& p) {
    return p ? std::optional(p->az_deg) : std::nullopt;
  };
  auto el = [](const std::optional<control::AzEl>& p) {
    return p ? std::optional(p->el_deg) : std::nullopt;
  };
  return astro::format_iso8601_utc_unix(s.unix_s) + ',' + field(az(s.demand), 5) + ',' +
         field(el(s.demand), 5) + ',' + field(az(s.reading), 5) + ',' + field(el(s.reading), 5) +
         ',' + field(err_az, 5) + ',' + field(err_el, 5) + ',' + field(s.power_db, 3) + ',' +
         s.mode + '\n';
}

}  // namespace

std::string recording_file_name(double unix_s) {
  // "2026-11-29T16:35:00.150Z" -> "20261129T163500Z": sortable, and no ':' for other systems.
  std::string stamp;
  for (const char c : astro::format_iso8601_utc_unix(std::floor(unix_s)).substr(0, 19)) {
    if (c != '-' && c != ':') stamp += c;
  }
  return "recording-" + stamp + "Z.csv";
}

bool is_recording_file_name(const std::string& name) {
  const std::string pattern = "recording-DDDDDDDDTDDDDDDZ.csv";
  if (name.size() != pattern.size()) return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const bool ok = pattern[i] == 'D' ? std::isdigit(static_cast<unsigned char>(name[i])) != 0
                                      : name[i] == pattern[i];
    if (!ok) return false;
  }
  return true;
}

const char* recording_csv_header() {
  return "utc,demand_az_deg,demand_el_deg,reading_az_deg,reading_el_deg,error_az_deg,"
         "error_el_deg,power_db,mode";
}

Result<bool> Recorder::start(double rate_hz, std::size_t max_bytes, double now_s, double unix_s) {
  if (running()) return fail("a recording is running: stop it first");
  if (!(rate_hz >= limits_.min_rate_hz && rate_hz <= limits_.max_rate_hz)) {
    return fail("rate_hz: must be 0.1 to 50");
  }
  if (max_bytes < 4096) return fail("max_mb: too small");
  state_ = "recording";
  file_ = recording_file_name(unix_s);
  reason_.clear();
  batch_ = std::string(recording_csv_header()) + '\n';
  batch_count_ = 0;
  first_ = true;
  rate_hz_ = rate_hz;
  max_bytes_ = max_bytes;
  rows_ = 0;
  bytes_ = batch_.size();
  next_s_ = now_s;
  batch_start_s_ = now_s;
  return true;
}

void Recorder::sample(double now_s, const RecordingSample& sample) {
  if (!running()) return;
  // Rows fall on a grid from the start, so their count is rate × time whatever the ticks' jitter;
  // a tick up to a quarter period early still takes its row (the loop's ticks are not exact).
  const double period_s = 1.0 / rate_hz_;
  if (now_s >= next_s_ - 0.25 * period_s) {
    take(sample);
    next_s_ += period_s;
    // Behind by more than a row (a stalled loop, a rate above the tick's): skip, do not burst.
    if (next_s_ < now_s) next_s_ = now_s + period_s;
  }
  if (running() &&
      (batch_count_ >= limits_.batch_rows || now_s - batch_start_s_ >= limits_.batch_s)) {
    flush();
    batch_start_s_ = now_s;
  }
}

void Recorder::take(const RecordingSample& sample) {
  std::string row = csv_row(sample);
  if (bytes_ + row.size() > max_bytes_) {
    stop("the size cap was reached (" + std::to_string(max_bytes_) + " bytes)");
    return;
  }
  bytes_ += row.size();
  batch_ += row;
  ++batch_count_;
  ++rows_;
}

void Recorder::flush() {
  if (batch_.empty()) return;
  write_(file_, std::move(batch_), first_);
  batch_.clear();
  batch_count_ = 0;
  first_ = false;
}

void Recorder::stop(const std::string& why) {
  if (!running()) return;
  flush();
  state_ = "stopped";
  reason_ = why;
}

void Recorder::write_failed(const std::string& name, const std::string& why) {
  if (name != file_ || state_ == "failed") return;  // an earlier recording's, already ended
  batch_.clear();
  batch_count_ = 0;
  state_ = "failed";
  reason_ = "could not write " + name + ": " + why;
}

nlohmann::json Recorder::to_json() const {
  nlohmann::json j{{"state", state_},
                   {"file", file_.empty() ? nlohmann::json(nullptr) : nlohmann::json(file_)},
                   {"rows", rows_},
                   {"bytes", bytes_},
                   {"rate_hz", rate_hz_},
                   {"max_bytes", max_bytes_},
                   {"reason", reason_}};
  return j;
}

}  // namespace azt::app
