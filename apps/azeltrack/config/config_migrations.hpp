#pragma once

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace azt::app {

/// The configuration layout this build writes and reads. A file without `schema_version` is
/// version 0 (the layout of the first releases); newer versions than this are refused, not guessed.
inline constexpr int kSchemaVersion = 2;

/// What migrate_config() did, one sentence per change ("[station].height_m renamed to alt_m").
struct MigrationReport {
  int from_version = kSchemaVersion;
  std::vector<std::string> changes;
};

/// Brings a parsed configuration to kSchemaVersion in place, one ordered, idempotent step per
/// version (OctoPrint's migrators): migrating an already-current table changes nothing. Throws
/// UsageError for a schema_version that is not an integer, below 0, or newer than this build.
MigrationReport migrate_config(toml::table& root);

}  // namespace azt::app
