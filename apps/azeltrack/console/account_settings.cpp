// The console's account settings, saved for account_api.cpp once it has checked who asks: the
// password's hash, the API tokens' records, and a whole settings file imported. Each is one
// save through the atomic store, off the loop.
#include "console/daemon_console.hpp"

#include "azt/astro/time_scales.hpp"
#include "common/usage_error.hpp"

namespace azt::app {

using json = nlohmann::json;

void DaemonConsole::save_password_hash(const std::string& hash, ActDone done) {
  save(
      "new_password",
      [hash](toml::table& root) {
        if (!root.contains("web")) root.insert("web", toml::table{});
        root["web"].as_table()->insert_or_assign("password_hash", hash);
      },
      [this, hash] {
        p_.config.web.password_hash = hash;
        return json::object();
      },
      std::move(done));
}

void DaemonConsole::save_tokens(const json& tokens, ActDone done) {
  save(
      "label",
      [tokens](toml::table& root) {
        toml::array items;
        for (const auto& t : tokens) {
          items.push_back(toml::table{{"label", t["label"].get<std::string>()},
                                      {"sha256", t["sha256"].get<std::string>()},
                                      {"created_utc", t["created_utc"].get<std::string>()}});
        }
        if (items.empty()) {
          root.erase("token");
        } else {
          root.insert_or_assign("token", std::move(items));
        }
      },
      [this] {
        p_.config.web.tokens = p_.store.config().web.tokens;
        return json::object();
      },
      std::move(done));
}

std::optional<std::string> DaemonConsole::config_file_text() { return p_.store.save_base().text; }

std::string DaemonConsole::utc_now_text() { return astro::format_iso8601_utc_unix(p_.unix_s()); }

void DaemonConsole::import_config_file(const std::string& text, ActDone done) {
  toml::table imported;
  try {
    imported = toml::parse(std::string_view(text), std::string_view("the imported file"));
  } catch (const toml::parse_error& e) {
    throw ApiError(400, "file",
                   "not TOML: line " + std::to_string(e.source().begin.line) + ": " +
                       std::string(e.description()));
  }
  save(
      "file",
      [imported](toml::table& root) {
        // The password and the tokens stay this station's: an import never changes who may act.
        toml::table next = imported;
        if (next.contains("web") && !next["web"].is_table())
          throw UsageError("[web] must be a table");
        if (!next.contains("web")) next.insert("web", toml::table{});
        toml::table& web = *next["web"].as_table();
        const toml::table* here = root["web"].as_table();
        for (const char* key : {"password_hash", "api_token_sha256"}) {
          web.erase(key);
          if (const toml::node* kept = here != nullptr ? here->get(key) : nullptr) {
            web.insert_or_assign(key, *kept);
          }
        }
        if (web.empty()) next.erase("web");
        next.erase("token");
        if (const toml::node* tokens = root.get("token")) next.insert_or_assign("token", *tokens);
        root = std::move(next);
      },
      [this] {
        return json{{"restart_needed", restart_needed_}};
      },
      std::move(done));
}

}  // namespace azt::app
