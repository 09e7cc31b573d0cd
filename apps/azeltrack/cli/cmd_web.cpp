// `azeltrack web password|token`: the console's credentials, saved through the configuration
// store (docs/web-api.md). Only hashes are stored; the token is shown once.
#include <termios.h>
#include <unistd.h>

#include <csignal>
#include <iostream>
#include <memory>
#include <string>

#include "azt/astro/time_scales.hpp"
#include "cli/commands.hpp"
#include "common/sky_setup.hpp"
#include "common/usage_error.hpp"
#include "config/config_store.hpp"
#include "config/daemon_config.hpp"
#include "config/token_label.hpp"
#include "console/web_auth.hpp"

namespace azt::app {
namespace {

struct WebOptions {
  std::string path;
  bool generate = false;
  std::string label;   ///< token --label: a [[token]] item of that name
  std::string revoke;  ///< token --revoke LABEL
  bool list = false;   ///< token --list
};

toml::array& token_items(toml::table& root) {
  if (!root.contains("token")) root.insert("token", toml::array{});
  toml::array* items = root["token"].as_array();
  if (items == nullptr) throw UsageError("token is not an array of tables");
  return *items;
}

bool has_label(const toml::array& items, const std::string& label) {
  for (const auto& item : items) {
    const auto* t = item.as_table();
    if (t != nullptr && t->get("label") != nullptr && (*t)["label"].value_or("") == label)
      return true;
  }
  return false;
}

/// A [[token]] of that label: its digest saved, the token printed once.
int make_labelled_token(const std::string& path, const std::string& label) {
  if (const auto why = token_label_problem(label)) throw UsageError("--label " + *why);
  const std::string token = random_hex(32);
  ConfigStore store = ConfigStore::open(path);
  auto saved = store.update([&](toml::table& root) {
    toml::array& items = token_items(root);
    if (has_label(items, label)) {
      throw UsageError("a token is already called \"" + label + "\": --revoke it first");
    }
    items.push_back(
        toml::table{{"label", label},
                    {"sha256", sha256_hex(token)},
                    {"created_utc", astro::format_iso8601_utc_unix(utc_now().unix_seconds())}});
  });
  if (!saved) throw UsageError(saved.error().message);
  std::cout << token << '\n';
  std::cerr
      << "saved its SHA-256 as \"" << label
      << "\"; a running daemon takes it at its next start (the console's tokens apply at once)\n";
  return 0;
}

int revoke_token(const std::string& path, const std::string& label) {
  ConfigStore store = ConfigStore::open(path);
  auto saved = store.update([&](toml::table& root) {
    toml::array& items = token_items(root);
    if (!has_label(items, label)) throw UsageError("no token is called \"" + label + "\"");
    for (auto it = items.begin(); it != items.end();) {
      const auto* t = it->as_table();
      const bool match = t != nullptr && (*t)["label"].value_or(std::string()) == label;
      it = match ? items.erase(it) : std::next(it);
    }
    if (items.empty()) root.erase("token");
  });
  if (!saved) throw UsageError(saved.error().message);
  std::cerr << "revoked \"" << label << "\"\n";
  return 0;
}

int list_tokens(const std::string& path) {
  const DaemonConfig c = load_daemon_config(path);
  for (const WebToken& t : c.web.tokens) {
    std::cout << t.label << '\t' << (t.created_utc.empty() ? "-" : t.created_utc) << '\n';
  }
  if (!c.web.api_token_sha256.empty()) std::cout << "[web] api_token_sha256\t-\n";
  return 0;
}

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

/// The terminal as it was before the echo went off: restored by the reader, or by Ctrl-C.
termios g_saved_terminal{};

extern "C" void restore_terminal_and_exit(int sig) {
  // Async-signal-safe: tcsetattr, signal and raise are.
  (void)tcsetattr(STDIN_FILENO, TCSAFLUSH, &g_saved_terminal);
  (void)std::signal(sig, SIG_DFL);
  (void)std::raise(sig);
}

/// One line typed on the terminal without echo (a password must not show on the screen). The
/// echo goes off before the prompt shows, and nothing typed after the prompt is flushed: what
/// is typed (or pasted) as soon as the prompt appears is read, never silently dropped.
std::string ask_hidden(const char* prompt) {
  std::string line;
  const bool quiet = tcgetattr(STDIN_FILENO, &g_saved_terminal) == 0;
  if (quiet) {
    termios hidden = g_saved_terminal;
    hidden.c_lflag &= ~static_cast<tcflag_t>(ECHO);
    (void)std::signal(SIGINT, restore_terminal_and_exit);
    (void)std::signal(SIGTERM, restore_terminal_and_exit);
    (void)tcsetattr(STDIN_FILENO, TCSAFLUSH, &hidden);
  }
  std::cerr << prompt << std::flush;
  std::getline(std::cin, line);
  if (quiet) {
    (void)tcsetattr(STDIN_FILENO, TCSADRAIN, &g_saved_terminal);
    (void)std::signal(SIGINT, SIG_DFL);
    (void)std::signal(SIGTERM, SIG_DFL);
  }
  std::cerr << '\n';
  return line;
}

/// The new password: generated; asked twice on a terminal, unseen; or the first line of
/// standard input, saying so (a pipe, or a service with no terminal, would otherwise seem hung).
std::string read_password(bool generate) {
  if (generate) return random_password();
  std::string password;
  if (isatty(STDIN_FILENO) != 0) {
    password = ask_hidden("New web console password (8 characters or more; not shown): ");
    if (password.size() >= 8 && ask_hidden("The same again: ") != password) {
      throw UsageError("the two passwords differ: nothing saved");
    }
  } else {
    std::cerr << "azeltrack web password: reading the new password from standard input (one "
                 "line, 8 characters or more)\n";
    if (!std::getline(std::cin, password)) {
      throw UsageError("no password on standard input: nothing saved");
    }
  }
  if (password.size() < 8) {
    throw UsageError("the password needs at least 8 characters: nothing saved");
  }
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
  token->add_option("--label", opts->label,
                    "Make a labelled token ([[token]]), listed and revoked by that name (the "
                    "console's Settings, --list, --revoke); without: [web] api_token_sha256");
  token->add_option("--revoke", opts->revoke, "Revoke the token of that label");
  token->add_flag("--list", opts->list, "List the tokens' labels and when they were made");
  return [opts, password] {
    if (password->parsed()) {
      const std::string pw = read_password(opts->generate);
      save_key(opts->path, "password_hash", hash_password(pw));
      if (opts->generate) std::cout << pw << '\n';
      std::cerr << "saved; restart the daemon to use it\n";
      return 0;
    }
    if (opts->list) return list_tokens(opts->path);
    if (!opts->revoke.empty()) return revoke_token(opts->path, opts->revoke);
    if (!opts->label.empty()) return make_labelled_token(opts->path, opts->label);
    const std::string t = random_hex(32);
    save_key(opts->path, "api_token_sha256", sha256_hex(t));
    std::cout << t << '\n';
    std::cerr
        << "saved its SHA-256; restart the daemon; send it as `Authorization: Bearer <token>`\n";
    return 0;
  };
}

}  // namespace azt::app
