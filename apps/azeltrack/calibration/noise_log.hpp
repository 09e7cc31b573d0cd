#pragma once
// The noise measurements' log as the console shows it (docs/calibration.md "Sun noise"): the
// JSON lines of noise-log.jsonl, newest first. Blocks on the disk: run it off the event loop.

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace azt::app {

/// {"entries": [the newest `max_entries` records, newest first], "bad_lines": N (lines that are
/// not a JSON object: a torn write, an edit)}; a missing file is an empty log.
nlohmann::json read_noise_log(const std::string& path, std::size_t max_entries = 500);

}  // namespace azt::app
