// `azeltrack config check|get|set`: the configuration file through the same validated, atomic,
// locked path the daemon uses for runtime changes (docs/configuration.md); `config schema`: the
// description of every key that path checks against.
#include <spdlog/spdlog.h>

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "common/usage_error.hpp"
#include "config/config_migrations.hpp"
#include "config/config_store.hpp"
#include "config/schema_json.hpp"
#include "config/schema_markdown.hpp"

namespace azt::app {
namespace {

struct ConfigOptions {
  std::string path;
  std::string key;
  std::string value;
  bool json = false;
  bool markdown = false;
};

ConfigStore open_logged(const std::string& path) {
  ConfigStore store = ConfigStore::open(path);
  for (const auto& notice : store.notices()) spdlog::warn("{}", notice);
  return store;
}

}  // namespace

Runner add_config_command(CLI::App& app) {
  auto opts = std::make_shared<ConfigOptions>();
  CLI::App* cmd = app.add_subcommand(
      "config", "Check, read or change a configuration file safely (validated, atomic, .bak kept)");
  cmd->require_subcommand(1);
  CLI::App* check = cmd->add_subcommand("check", "Validate; print problems with key and line");
  CLI::App* get =
      cmd->add_subcommand("get", "Print one value as TOML (KEY like control.window_deg)");
  CLI::App* set = cmd->add_subcommand(
      "set", "Set one value (TOML: 0.2, \"FN31\", true; array items as park.2.az_deg) and save");
  CLI::App* schema = cmd->add_subcommand(
      "schema", "Print every key: type, range, default, when it applies (docs/configuration.md)");
  auto* as_json = schema->add_flag("--json", opts->json, "As JSON (GET /api/config/schema's form)");
  schema->add_flag("--markdown", opts->markdown, "As docs/configuration.md's reference (default)")
      ->excludes(as_json);
  for (CLI::App* sub : {check, get, set}) {
    sub->add_option("--config", opts->path, "Configuration file")->required();
  }
  get->add_option("key", opts->key, "Dotted key")->required();
  set->add_option("key", opts->key, "Dotted key")->required();
  set->add_option("value", opts->value, "TOML value")->required();
  return [opts, check, get, schema] {
    if (schema->parsed()) {
      std::cout << (opts->json ? schema_json().dump(2) : schema_markdown()) << '\n';
      return 0;
    }
    if (check->parsed()) {
      const ConfigStore store = open_logged(opts->path);
      std::cout << store.path() << ": valid (schema " << kSchemaVersion << ")\n";
      return 0;
    }
    if (get->parsed()) {
      const ConfigStore store = open_logged(opts->path);
      const auto value = store.get(opts->key);
      if (!value) throw UsageError("'" + opts->key + "' is not set in " + opts->path);
      std::cout << *value << '\n';
      return 0;
    }
    ConfigStore store = open_logged(opts->path);
    const std::size_t logged = store.notices().size();
    auto saved = store.set(opts->key, opts->value);
    if (!saved) throw UsageError(saved.error().message);
    for (std::size_t i = logged; i < store.notices().size(); ++i) {
      spdlog::warn("{}", store.notices()[i]);  // a corrupt file set aside while saving
    }
    return 0;
  };
}

}  // namespace azt::app
