// POST /api/recording and /api/recording/stop, and the files read for the console off the loop:
// GET /api/recordings (the list), /api/recordings/NAME (a download), /api/noise/log
// (docs/web-api.md, docs/calibration.md "Recording").
#include <memory>
#include <string>

#include "calibration/noise_log.hpp"
#include "calibration/recording_files.hpp"
#include "console/body_fields.hpp"
#include "console/daemon_console.hpp"

namespace azt::app {

using json = nlohmann::json;

namespace {

/// The most a recording may grow to, MiB, when the request does not say; and the most it may ask.
constexpr double kDefaultRecordingMb = 16.0;
constexpr double kMaxRecordingMb = 64.0;

}  // namespace

json DaemonConsole::act_recording(const std::string& action, const json& body,
                                  const std::string& source) {
  if (p_.recorder == nullptr) throw ApiError(503, "", "no recording here");
  if (action == "recording/stop") {
    p_.recorder->stop("stopped by " + source);
    return {{"recording", p_.recorder->to_json()}};
  }
  const double rate_hz = body_number(body, "rate_hz");
  if (!(rate_hz >= 0.1 && rate_hz <= 50.0)) {
    throw ApiError(400, "rate_hz", "rate_hz must be 0.1 to 50");
  }
  const double max_mb = body_optional_number(body, "max_mb").value_or(kDefaultRecordingMb);
  if (!(max_mb >= 1.0 && max_mb <= kMaxRecordingMb)) {
    throw ApiError(400, "max_mb", "max_mb must be 1 to 64");
  }
  if (p_.recorder->running()) throw ApiError(409, "", "a recording is running: stop it first");
  const auto bytes = static_cast<std::size_t>(max_mb * 1024.0 * 1024.0);
  if (auto ok = p_.recorder->start(rate_hz, bytes, p_.monotonic_s(), p_.unix_s()); !ok) {
    throw ApiError(409, "", ok.error().message);
  }
  p_.log(source + ": recording " + p_.recorder->to_json().value("file", ""));
  return {{"recording", p_.recorder->to_json()}};
}

void DaemonConsole::read_later(const std::string& route, ActDone done) {
  auto answer = std::make_shared<ActResult>();
  std::function<void()> work;
  if (route == "noise/log" && !p_.noise_log.empty()) {
    work = [answer, path = p_.noise_log] { answer->fields = read_noise_log(path); };
  } else if (route == "recordings" && !p_.recordings_dir.empty()) {
    work = [answer, dir = p_.recordings_dir] { answer->fields = list_recordings(dir); };
  } else if (route.rfind("recordings/", 0) == 0 && !p_.recordings_dir.empty()) {
    const std::string name = route.substr(11);
    // Checked on the loop too: only a recording's own name is ever joined to the folder.
    if (!is_recording_file_name(name)) throw ApiError(404, "", "no such recording: " + name);
    work = [answer, dir = p_.recordings_dir, name] {
      auto text = read_recording(dir, name);
      if (!text) {
        answer->error = ApiError(404, "", text.error().message);
        return;
      }
      answer->fields = {{"download", name}, {"content_type", "text/csv"}, {"text", *text}};
    };
  } else {
    throw ApiError(404, "", "no such page: /api/" + route);
  }
  p_.offload(std::move(work), [answer, done = std::move(done)] { done(std::move(*answer)); });
}

}  // namespace azt::app
