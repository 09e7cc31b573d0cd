// The account through the HTTP API (docs/web-api.md "The account"): API tokens listed, made and
// revoked; the password changed with the old one; the whole settings file exported and imported.
// Every route here comes after authorize(); what is saved goes through the model's one save.
#include <algorithm>
#include <cctype>
#include <memory>

#include "config/daemon_config.hpp"
#include "config/token_label.hpp"
#include "console/api_reply.hpp"
#include "console/web_api.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

constexpr std::size_t kMinPasswordChars = 8;
constexpr std::size_t kMaxTokens = 32;

/// "/api/tokens/logger%20script" -> "logger script"; nullopt for a malformed escape.
std::optional<std::string> percent_decoded(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      out += text[i];
      continue;
    }
    if (i + 2 >= text.size() || !std::isxdigit(static_cast<unsigned char>(text[i + 1])) ||
        !std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      return std::nullopt;
    }
    out += static_cast<char>(std::stoi(std::string(text.substr(i + 1, 2)), nullptr, 16));
    i += 2;
  }
  return out;
}

std::optional<json> json_object(const std::string& body) {
  json parsed = json::parse(body, nullptr, false);
  if (parsed.is_discarded() || !parsed.is_object()) return std::nullopt;
  return parsed;
}

std::string text_field(const json& body, const char* key) {
  return body.contains(key) && body[key].is_string() ? body[key].get<std::string>() : "";
}

/// The tokens as saved, for the running check.
std::vector<ApiToken> tokens_of(const json& records) {
  std::vector<ApiToken> out;
  for (const auto& r : records) {
    out.push_back({r["label"].get<std::string>(), r["sha256"].get<std::string>(),
                   r["created_utc"].get<std::string>(), false});
  }
  return out;
}

/// The model's answer, or its refusal, as the HTTP reply.
ActDone reply_to(const WebApi::Respond& respond, const json& fields) {
  return [respond, fields](ActResult result) {
    if (result.error) {
      respond(error_reply(result.error->status(), result.error->what(), result.error->field()));
      return;
    }
    json body{{"ok", true}};
    body.update(fields);
    body.update(result.fields);
    respond(json_reply(200, body));
  };
}

}  // namespace

bool WebApi::handle_account(const linux_os::HttpRequest& request, const Respond& respond) {
  const std::string& p = request.path;
  const std::string& m = request.method;
  if (p == "/api/tokens" && m == "GET") {
    list_tokens(respond);
  } else if (p == "/api/tokens" && m == "POST") {
    create_token(request, respond);
  } else if (p.rfind("/api/tokens/", 0) == 0 && m == "DELETE") {
    const auto label = percent_decoded(std::string_view(p).substr(12));
    if (!label) {
      respond(error_reply(400, "the token's label is not a valid address part", "label"));
    } else {
      revoke_token(*label, respond);
    }
  } else if (p == "/api/password" && m == "POST") {
    change_password(request, respond);
  } else if (p == "/api/config/file" && m == "GET") {
    const auto text = model_.config_file_text();
    respond(text ? linux_os::HttpReply{200,
                                       "text/plain; charset=utf-8",
                                       *text,
                                       {{"Content-Disposition",
                                         "attachment; filename=\"azeltrack.toml\""}}}
                 : error_reply(404, "no settings file here"));
  } else if (p == "/api/config/file" && m == "PUT") {
    import_file(request, respond);
  } else {
    return false;
  }
  return true;
}

void WebApi::list_tokens(const Respond& respond) const {
  json out = json::array();
  for (const ApiToken& t : auth_.tokens()) {
    out.push_back({{"label", t.label}, {"created_utc", t.created_utc}, {"legacy", t.legacy}});
  }
  respond(json_reply(200, json{{"tokens", out}}));
}

json WebApi::token_records(const std::optional<ApiToken>& with, const std::string& without) const {
  json records = json::array();
  auto add = [&records](const ApiToken& t) {
    records.push_back({{"label", t.label}, {"sha256", t.sha256}, {"created_utc", t.created_utc}});
  };
  for (const ApiToken& t : auth_.tokens()) {
    if (!t.legacy && t.label != without) add(t);
  }
  if (with) add(*with);
  return records;
}

void WebApi::take_tokens(const json& records) {
  std::vector<ApiToken> next = tokens_of(records);
  for (const ApiToken& t : auth_.tokens()) {
    if (t.legacy) next.push_back(t);  // [web] api_token_sha256 is not a record: it stays
  }
  auth_.set_tokens(std::move(next));
}

void WebApi::create_token(const linux_os::HttpRequest& request, const Respond& respond) {
  const auto body = json_object(request.body);
  const std::string label = body ? text_field(*body, "label") : "";
  if (const auto why = token_label_problem(label)) {
    respond(error_reply(400, "label " + *why, "label"));
    return;
  }
  const auto& tokens = auth_.tokens();
  if (std::any_of(tokens.begin(), tokens.end(),
                  [&](const ApiToken& t) { return t.label == label; })) {
    respond(
        error_reply(409, "a token is already called \"" + label + "\": revoke it first", "label"));
    return;
  }
  if (tokens.size() >= kMaxTokens) {
    respond(error_reply(409, "32 tokens are the most: revoke one first", "label"));
    return;
  }
  const std::string token = random_hex(32);
  ApiToken made{label, sha256_hex(token), model_.utc_now_text(), false};
  // The token itself is in this answer only: the settings keep its digest.
  json records = token_records(made, "");
  model_.save_tokens(records, [this, respond, records, label, token](ActResult result) {
    if (!result.error) take_tokens(records);
    reply_to(respond, json{{"label", label}, {"token", token}})(std::move(result));
  });
}

void WebApi::revoke_token(const std::string& label, const Respond& respond) {
  const auto& tokens = auth_.tokens();
  const auto it = std::find_if(tokens.begin(), tokens.end(),
                               [&](const ApiToken& t) { return t.label == label; });
  if (it == tokens.end()) {
    respond(error_reply(404, "no token called \"" + label + "\"", "label"));
    return;
  }
  if (it->legacy) {
    respond(error_reply(409,
                        "this is [web] api_token_sha256: remove it with `azeltrack config set` and "
                        "a restart, or make labelled tokens instead",
                        "label"));
    return;
  }
  json records = token_records(std::nullopt, label);
  model_.save_tokens(records, [this, respond, records, label](ActResult result) {
    if (!result.error) take_tokens(records);
    reply_to(respond, json{{"revoked", label}})(std::move(result));
  });
}

void WebApi::change_password(const linux_os::HttpRequest& request, const Respond& respond) {
  const auto body = json_object(request.body);
  const std::string old_password = body ? text_field(*body, "old_password") : "";
  const std::string new_password = body ? text_field(*body, "new_password") : "";
  if (new_password.size() < kMinPasswordChars || new_password.size() > 1024) {
    respond(error_reply(400, "the new password needs 8 to 1024 characters", "new_password"));
    return;
  }
  // The check of the old one and the hash of the new one take ~0.1 s each: off the loop. The
  // old one is checked like a login, so its failures count against the login limit.
  const auto ticket = auth_.begin_login(request.client, now_());
  if (ticket.outcome != WebAuth::LoginOutcome::Checking) {
    respond(error_reply(429, "too many failed attempts: try again later", "old_password"));
    return;
  }
  auto outcome = std::make_shared<std::pair<bool, std::string>>(false, "");
  offload_(
      [outcome, hash = auth_.password_hash(), old_password, new_password] {
        outcome->first = !hash.empty() && verify_password(hash, old_password);
        if (outcome->first) outcome->second = hash_password(new_password);
      },
      [this, outcome, respond, client = request.client,
       session = cookie_value(request.cookie, "azt_session")] {
        if (auth_.finish_login(client, outcome->first, now_()).outcome !=
            WebAuth::LoginOutcome::Ok) {
          respond(error_reply(401, "the current password is wrong", "old_password"));
          return;
        }
        model_.save_password_hash(outcome->second, [this, outcome, respond, session](ActResult r) {
          // Other sessions end with the old password; this one goes on.
          if (!r.error) auth_.set_password_hash(outcome->second, session);
          reply_to(respond, json::object())(std::move(r));
        });
      });
}

void WebApi::import_file(const linux_os::HttpRequest& request, const Respond& respond) {
  model_.import_config_file(request.body, reply_to(respond, json::object()));
}

}  // namespace azt::app
