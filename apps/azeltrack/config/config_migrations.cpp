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

/// [mount.AXIS], made when missing.
toml::table& mount_axis_table(toml::table& root, const std::string& axis) {
  if (!root.contains("mount")) root.insert("mount", toml::table{});
  toml::table* mount = root["mount"].as_table();
  if (mount == nullptr) throw UsageError("[mount] must be a table");
  if (!mount->contains(axis)) mount->insert(axis, toml::table{});
  toml::table* t = (*mount)[axis].as_table();
  if (t == nullptr) throw UsageError("[mount." + axis + "] must be a table");
  return *t;
}

/// One key of [sim.AXIS] carried to [mount.AXIS] as `new_key`: moved, or copied (kept in both).
struct Carry {
  const char* key;
  const char* new_key;
  bool move;
};

void carry_key(toml::table& root, toml::table& plant, const std::string& axis, const Carry& c,
               MigrationReport& report) {
  const toml::node* value = plant.get(c.key);
  if (value == nullptr) return;
  toml::table& target = mount_axis_table(root, axis);
  std::string from = "[sim." + axis + "].";
  from += c.key;
  std::string to = "[mount." + axis + "].";
  to += c.new_key;
  if (target.contains(c.new_key)) {
    throw UsageError(from + " and " + to + " are both set: keep " + to + " only");
  }
  target.insert(c.new_key, *value);
  if (c.move) plant.erase(c.key);
  std::string change = from;
  change += c.move ? " moved to " : " copied to ";
  change += to;
  report.changes.push_back(std::move(change));
}

/// 1 -> 2: the mount's rate and encoder resolution lived in the simulator's tables ([sim.az]),
/// and the real station's controller read them from there. They move to
/// [mount.az] / [mount.el]; the motor model the controller also uses (time constant, stiction,
/// backlash) is copied there too, and stays in [sim.*] as the simulated plant's, so a migrated
/// file drives the same controller and the same simulation.
void migrate_1_to_2(toml::table& root, MigrationReport& report) {
  toml::table* sim = root["sim"].as_table();
  if (sim == nullptr) return;
  constexpr Carry kCarried[] = {{"max_rate_deg_s", "max_rate_deg_s", true},
                                {"encoder_bits", "encoder_bits", true},
                                {"time_constant_s", "time_constant_s", false},
                                {"stiction_duty", "min_duty", false},
                                {"backlash_deg", "backlash_deg", false}};
  for (const std::string axis : {"az", "el"}) {
    toml::table* plant = (*sim)[axis].as_table();
    if (plant == nullptr) continue;
    for (const Carry& c : kCarried) carry_key(root, *plant, axis, c, report);
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
  constexpr Step kSteps[kSchemaVersion] = {migrate_0_to_1, migrate_1_to_2};
  for (int v = report.from_version; v < kSchemaVersion; ++v) kSteps[v](root, report);
  if (report.from_version != kSchemaVersion) {
    root.insert_or_assign("schema_version", std::int64_t{kSchemaVersion});
    report.changes.emplace_back("schema_version " + std::to_string(report.from_version) + " -> " +
                                std::to_string(kSchemaVersion));
  }
  return report;
}

}  // namespace azt::app
