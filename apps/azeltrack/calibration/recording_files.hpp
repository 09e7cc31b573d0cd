#pragma once
// The recordings' files under `recordings/` in the state directory (docs/calibration.md
// "Recording"): appended batch by batch, listed, read back for a download. Every function here
// blocks on the disk: the daemon calls them on its worker thread, never on the event loop.

#include <string>

#include <nlohmann/json.hpp>

#include "azt/util/result.hpp"

namespace azt::app {

/// Appends `text` to the recording `name` in `dir` (the folder made when missing); `first`
/// creates the file and fails if it exists (two recordings started in one second). No fsync:
/// a batch every two seconds would wear an SD card, and a power cut loses at most a batch.
Result<bool> append_recording(const std::string& dir, const std::string& name,
                              const std::string& text, bool first);

/// {"recordings": [{"name", "bytes", "rows"}]}, newest first (rows: lines after the header).
nlohmann::json list_recordings(const std::string& dir);

/// A recording's text; fails for a name recording_file_name() does not make (no path can be
/// reached through it) or a file that is not there.
Result<std::string> read_recording(const std::string& dir, const std::string& name);

}  // namespace azt::app
