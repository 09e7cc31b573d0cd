// `azeltrack web password|token`: the console's credentials, saved through the configuration
// store (docs/web-api.md). Only hashes are stored; the token is shown once.
#include <unistd.h>

#include <iostream>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "common/usage_error.hpp"
#include "config/config_store.hpp"
#include "console/web_auth.hpp"

namespace azt::app {
namespace {

struct WebOptions {
  std::string path;
  bool generate = false;
};

void save_key(const std::string& path, const std::string& key, const std::string& value) {
  ConfigStore store = ConfigStore::open(path);
  auto saved = store.update([&](toml::table& root) {
    if (!root.contains("web")) root.insert("web", toml::table{});
    toml::table* web = root["web"].as_table();
    if (web == nullptr) throw UsageError("[web] is not a table");
    web->insert_or_assign(key, value);
  });
  if (!saved) throw UsageError(saved.error().message);
}

/// The new password: generated, or the first line of stdin (a terminal is asked for it).
std::string read_password(bool generate) {
  if (generate) return random_password();
  if (isatty(STDIN_FILENO) != 0) std::cerr << "new web console password: " << std::flush;
  std::string password;
  std::getline(std::cin, password);
  if (password.size() < 8) throw UsageError("the password needs at least 8 characters");
  return password;
}

}  // namespace

Runner add_web_command(CLI::App& app) {
  auto opts = std::make_shared<WebOptions>();
  CLI::App* cmd = app.add_subcommand("web", "Set the web console's password or API token");
  cmd->require_subcommand(1);
  CLI::App* password = cmd->add_subcommand(
      "password", "Read a password from stdin (or --generate one) and save its Argon2id hash");
  CLI::App* token = cmd->add_subcommand(
      "token", "Generate a bearer token for scripts, print it once, save its SHA-256");
  for (CLI::App* sub : {password, token}) {
    sub->add_option("--config", opts->path, "Configuration file")->required();
  }
  password->add_flag("--generate", opts->generate, "Generate a password and print it");
  return [opts, password] {
    if (password->parsed()) {
      const std::string pw = read_password(opts->generate);
      save_key(opts->path, "password_hash", hash_password(pw));
      if (opts->generate) std::cout << pw << '\n';
      std::cerr << "saved; restart the daemon to use it\n";
      return 0;
    }
    const std::string t = random_hex(32);
    save_key(opts->path, "api_token_sha256", sha256_hex(t));
    std::cout << t << '\n';
    std::cerr
        << "saved its SHA-256; restart the daemon; send it as `Authorization: Bearer <token>`\n";
    return 0;
  };
}

}  // namespace azt::app
