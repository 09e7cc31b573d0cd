#include "config/config_migrations.hpp"

#include "common/usage_error.hpp"

namespace azt::app {
namespace {

/// 0 -> 1: the first releases named the station height `height_m`; the daemon issue fixed the
/// name as `alt_m`. Both present is a contradiction the user must resolve.
void migrate_0_to_1(toml::table& root, MigrationReport& report) {
  toml::table* station = root["station"].as_table();
  if (station != nullptr && station->contains("height_m")) {
    if (station->contains("alt_m")) {
      throw UsageError("[station] has both height_m (schema 0) and alt_m: keep alt_m only");
    }
    toml::node* old = station->get("height_m");
    station->insert("alt_m", *old);
    station->erase("height_m");
    report.changes.emplace_back("[station].height_m renamed to alt_m");
  }
}

int read_version(const toml::table& root) {
  const toml::node* n = root.get("schema_version");
  if (n == nullptr) return 0;
  const auto v = n->value<std::int64_t>();
  if (!n->is_integer() || !v || *v < 0) {
    throw UsageError("line " + std::to_string(n->source().begin.line) +
                     ": schema_version must be a non-negative integer");
  }
  if (*v > kSchemaVersion) {
    throw UsageError("schema_version " + std::to_string(*v) +
                     " is not supported by this azeltrack (" + std::to_string(kSchemaVersion) +
                     " is): refusing to guess");
  }
  return static_cast<int>(*v);
}

}  // namespace

MigrationReport migrate_config(toml::table& root) {
  MigrationReport report;
  report.from_version = read_version(root);
  using Step = void (*)(toml::table&, MigrationReport&);
  // steps[v] migrates version v to v + 1.
  constexpr Step kSteps[kSchemaVersion] = {migrate_0_to_1};
  for (int v = report.from_version; v < kSchemaVersion; ++v) kSteps[v](root, report);
  if (report.from_version != kSchemaVersion) {
    root.insert_or_assign("schema_version", std::int64_t{kSchemaVersion});
    report.changes.emplace_back("schema_version " + std::to_string(report.from_version) + " -> " +
                                std::to_string(kSchemaVersion));
  }
  return report;
}

}  // namespace azt::app
