#pragma once
// PUT /api/config/SECTION and /api/config/SECTION/N (docs/web-api.md): the keys a console sends,
// checked against the configuration schema before anything is saved, and the store change that
// writes them into the file as re-read. Which of them the running station takes at once, and
// through which of the console's apply paths, is live_apply_of().

#include <toml++/toml.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/config_schema.hpp"
#include "config/config_store.hpp"

namespace azt::app {

/// The console's ways of bringing a saved setting into the running station.
enum class LiveApply { Station, Band, DxGrid, Corrections, Park, Schedule, Pol };

/// How the running station takes `section`'s `key` once saved; nullopt: at the next start. The
/// keys the schema marks live are exactly those that have one.
std::optional<LiveApply> live_apply_of(std::string_view section, std::string_view key);

struct SettingsChange {
  const SectionSpec* section = nullptr;
  std::size_t item = 0;              ///< the [[table]] changed, from 1; 0 for a table section
  std::vector<const KeySpec*> keys;  ///< in the order of the request
  toml::table values;                ///< the keys to set
  std::vector<std::string> removed;  ///< the keys to remove (null: the default applies)

  /// "control.window_deg", "park.2.name": as `azeltrack config get|set` names it.
  [[nodiscard]] std::string dotted(const KeySpec& key) const;
  /// "[control]", "[park#2]": as the loader's errors name the table.
  [[nodiscard]] std::string table_name() const;
};

/// `route` is the path after "/api/config/" ("control", "mount.az", "park/2"). Throws ApiError:
/// 404 for a route that is no section, 400 naming the key for an unknown, secret, ill-typed or
/// out-of-range value, or for a body with no keys.
SettingsChange settings_change(std::string_view route, const nlohmann::json& body);

/// The items of an array of tables the file lacks before the one changed, as the station runs
/// them (the park slots it has defaults for); item `index` counts from 0.
using ItemFiller = std::function<toml::table(std::size_t index)>;

/// Sets and removes the change's keys in the file as re-read. Setting a station's grid removes
/// its position and setting its position removes its grid: one is derived from the other. An
/// item beyond the next new one is refused (UsageError) unless `fill` gives the ones between.
ConfigStore::Change store_change(const SettingsChange& change, ItemFiller fill = {});

}  // namespace azt::app
