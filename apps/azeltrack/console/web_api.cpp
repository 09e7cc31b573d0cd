#include "console/web_api.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>

#include "azt/linux/asio.hpp"
#include "console/api_reply.hpp"
#include "console/locator_api.hpp"
#include "console/query_string.hpp"
#include "console/web_assets.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

/// "host:port" or "[v6]:port" -> host.
std::string host_name(const std::string& host_header) {
  if (!host_header.empty() && host_header.front() == '[') {
    const auto close = host_header.find(']');
    return close == std::string::npos ? host_header : host_header.substr(1, close - 1);
  }
  const auto colon = host_header.rfind(':');
  return colon == std::string::npos ? host_header : host_header.substr(0, colon);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

double query_number(const std::string& query, const std::string& key, double fallback) {
  const auto text = query_value(query, key);
  if (!text) return fallback;
  try {
    const double v = std::stod(*text);
    return std::isfinite(v) ? v : fallback;
  } catch (const std::exception&) {
    return fallback;
  }
}

/// An action's answer: {"ok": true, …its fields} or its refusal.
ActDone answer(const WebApi::Respond& respond) {
  return [respond](ActResult result) {
    if (result.error) {
      respond(error_reply(result.error->status(), result.error->what(), result.error->field()));
      return;
    }
    json body{{"ok", true}};
    body.update(result.fields);
    respond(json_reply(200, body));
  };
}

/// The GET routes the model answers off the loop (files of the state directory).
bool read_later(const std::string& path) {
  return path == "/api/recordings" || path.rfind("/api/recordings/", 0) == 0 ||
         path == "/api/noise/log";
}

/// read_later's answer: its JSON, or the file it names as a download.
ActDone file_answer(const WebApi::Respond& respond) {
  return [respond](ActResult result) {
    if (result.error) {
      respond(error_reply(result.error->status(), result.error->what(), result.error->field()));
      return;
    }
    json& f = result.fields;
    if (!f.contains("download")) {
      respond(json_reply(200, f));
      return;
    }
    linux_os::HttpReply reply{200,
                              f.value("content_type", "text/plain"),
                              std::move(f["text"].get_ref<std::string&>()),
                              {}};
    reply.headers.emplace_back("Content-Disposition",
                               "attachment; filename=\"" + f["download"].get<std::string>() + "\"");
    respond(reply);
  };
}

}  // namespace

std::string cookie_value(const std::string& cookie_header, const std::string& name) {
  std::size_t start = 0;
  while (start < cookie_header.size()) {
    auto end = cookie_header.find(';', start);
    if (end == std::string::npos) end = cookie_header.size();
    std::string item = cookie_header.substr(start, end - start);
    item.erase(0, item.find_first_not_of(' '));
    if (item.size() > name.size() && item.compare(0, name.size(), name) == 0 &&
        item[name.size()] == '=') {
      return item.substr(name.size() + 1);
    }
    start = end + 1;
  }
  return "";
}

bool WebApi::host_allowed(const std::string& host) const {
  const std::string name = lower(host_name(host));
  if (name.empty()) return true;  // HTTP/1.0 clients send none
  boost::system::error_code ec;
  (void)boost::asio::ip::make_address(name, ec);
  if (!ec || name == "localhost") return true;
  return std::any_of(config_.allowed_hosts.begin(), config_.allowed_hosts.end(),
                     [&name](const std::string& h) { return lower(h) == name; });
}

bool WebApi::origin_matches(const linux_os::HttpRequest& request) {
  // Non-browser clients send no Origin; browsers always do on POST and WebSocket upgrades, so a
  // page from elsewhere is always caught here.
  if (request.origin.empty()) return true;
  return request.origin == "http://" + request.host || request.origin == "https://" + request.host;
}

std::optional<linux_os::HttpReply> WebApi::check_upgrade(
    const linux_os::HttpRequest& request) const {
  if (!host_allowed(request.host)) return error_reply(403, "Host not allowed");
  if (!origin_matches(request)) return error_reply(403, "cross-origin WebSocket refused");
  return std::nullopt;
}

void WebApi::handle(linux_os::HttpRequest request, const Respond& respond) {
  if (!host_allowed(request.host)) {
    respond(error_reply(
        403, "Host '" + request.host + "' is not allowed: add it to [web] allowed_hosts"));
    return;
  }
  try {
    if (request.method == "GET" && request.path == "/api/moon-windows") {
      model_.moon_windows(request.query, [respond](ActResult result) {
        if (result.error) {
          respond(error_reply(result.error->status(), result.error->what(), result.error->field()));
          return;
        }
        respond(json_reply(200, result.fields));
      });
    } else if (request.method == "GET" && request.path == "/api/software") {
      software_status(respond);
    } else if (request.method == "GET" &&
               (request.path == "/api/tokens" || request.path == "/api/config/file")) {
      // Reading these needs a login, as acting does: they say who may act.
      if (auto refusal = authorize(request)) {
        respond(*refusal);
      } else {
        handle_account(request, respond);
      }
    } else if (request.method == "GET" && read_later(request.path)) {
      model_.read_later(request.path.substr(5), file_answer(respond));
    } else if (request.method == "GET" || request.method == "HEAD") {
      respond(handle_get(request));
    } else if (request.method == "POST" || request.method == "PUT" ||
               (request.method == "DELETE" && request.path.rfind("/api/tokens/", 0) == 0)) {
      handle_action(request, respond);
    } else {
      respond(error_reply(405, "method not allowed"));
    }
  } catch (const ApiError& e) {
    respond(error_reply(e.status(), e.what(), e.field()));
  } catch (const std::exception& e) {
    // The daemon keeps running whatever a request does; the message says what went wrong.
    respond(error_reply(500, e.what()));
  }
}

linux_os::HttpReply WebApi::handle_get(const linux_os::HttpRequest& request) {
  const std::string& p = request.path;
  if (p == "/api/state") return json_reply(200, model_.state());
  if (p == "/api/config") return json_reply(200, model_.config());
  if (p == "/api/config/schema") return json_reply(200, model_.config_schema());
  if (p == "/api/targets") return json_reply(200, model_.targets());
  if (p == "/api/schedule") return json_reply(200, model_.schedule());
  if (p == "/api/sky") {
    return json_reply(
        200, model_.sky(std::clamp(query_number(request.query, "hours", 12.0), 0.0, 24.0)));
  }
  if (p == "/api/locator") return json_reply(200, locator_json(request.query));
  if (p == "/api/calibration/log") {
    auto csv = model_.scan_log_csv();
    if (!csv) return error_reply(404, "no scan log here");
    return linux_os::HttpReply{200, "text/csv; charset=utf-8", std::move(*csv), {}};
  }
  if (p.rfind("/api/calibration/", 0) == 0) {
    auto [status, body] = model_.calibration_view(p.substr(17));
    return json_reply(status, body);
  }
  if (p == "/api/session") {
    const auto csrf = auth_.csrf_of(cookie_value(request.cookie, "azt_session"), now_());
    json body{{"logged_in", csrf.has_value()}, {"password_set", auth_.has_password()}};
    if (csrf) body["csrf"] = *csrf;
    // A bearer token acts without a session (the kiosk, scripts): say whose it is.
    if (request.authorization.rfind("Bearer ", 0) == 0) {
      const auto label = auth_.bearer_label(std::string_view(request.authorization).substr(7));
      body["logged_in"] = label.has_value();
      if (label) body["token"] = *label;
    }
    return json_reply(200, body);
  }
  // The pages by their names: the console at "/", the 480×320 touch panel at "/panel".
  std::string_view page = p;
  if (p == "/") page = "/index.html";
  if (p == "/panel") page = "/panel.html";
  if (const WebAsset* asset = find_web_asset(page)) {
    return linux_os::HttpReply{200, std::string(asset->content_type), std::string(asset->body), {}};
  }
  return error_reply(404, "no such page: " + p);
}

std::optional<linux_os::HttpReply> WebApi::authorize(const linux_os::HttpRequest& request) const {
  if (!origin_matches(request)) return error_reply(403, "cross-origin request refused");
  if (request.authorization.rfind("Bearer ", 0) == 0) {
    if (auth_.bearer_ok(std::string_view(request.authorization).substr(7))) return std::nullopt;
    return error_reply(401, "login required: the bearer token is not valid");
  }
  const auto csrf = auth_.csrf_of(cookie_value(request.cookie, "azt_session"), now_());
  if (!csrf) return error_reply(401, "login required");
  if (request.csrf.empty() || !constant_time_equal(request.csrf, *csrf)) {
    return error_reply(403, "CSRF token missing or wrong");
  }
  return std::nullopt;
}

linux_os::HttpServer::BodyAllowance WebApi::body_allowance(const linux_os::HttpRequest& head) {
  linux_os::HttpServer::BodyAllowance allowance{linux_os::HttpServer::kMaxBodyBytes, {}, {}, {}};
  if (head.method == "POST" && head.path == "/api/satellites/elements") {
    // An element file is held whole (it is parsed whole): read only with a login, one at a time,
    // up to the size of CelesTrak's largest groups as TLE.
    if (!has_session(head)) {
      allowance.refusal = error_reply(401, "login required to upload element sets");
    } else if (!elements_slot_.expired()) {
      allowance.refusal = error_reply(409, "another element file is being uploaded");
    } else {
      auto slot = std::make_shared<const int>(0);
      elements_slot_ = slot;
      allowance.hold = std::move(slot);
      allowance.max_bytes = kMaxElementUploadBytes;
    }
    return allowance;
  }
  if (head.method == "POST" && head.path == "/api/calibration/log") {
    // A scan log is parsed whole: read only with a login, one at a time.
    if (!has_session(head)) {
      allowance.refusal = error_reply(401, "login required to import a scan log");
    } else if (!scan_log_slot_.expired()) {
      allowance.refusal = error_reply(409, "another scan log is being imported");
    } else {
      auto slot = std::make_shared<const int>(0);
      scan_log_slot_ = slot;
      allowance.hold = std::move(slot);
      allowance.max_bytes = kMaxScanLogUploadBytes;
    }
    return allowance;
  }
  const bool upload = software_ != nullptr && software_->enabled() && head.method == "POST" &&
                      head.path == "/api/software/update";
  if (!upload) return allowance;
  if (!has_session(head)) {
    allowance.refusal = error_reply(401, "login required to upload a package");
  } else if (!upload_slot_.expired()) {
    allowance.refusal =
        error_reply(409, "another package is being uploaded; try again when it is done");
  } else {
    auto slot = std::make_shared<const int>(0);
    upload_slot_ = slot;
    allowance.hold = std::move(slot);
    allowance.max_bytes = SoftwareUpdates::kMaxPackageBytes;
    allowance.sink = software_->start_upload();  // streamed to the inbox, never held whole
  }
  return allowance;
}

void WebApi::software_status(const Respond& respond) {
  if (software_ == nullptr) {
    respond(error_reply(404, "no software page here"));
    return;
  }
  software_->status(
      [respond](const ActResult& result) { respond(json_reply(200, result.fields)); });
}

bool WebApi::is_local_stop(const linux_os::HttpRequest& request) {
  // STOP only stops, and a stop must never wait for a password: from this machine (the touch
  // panel beside the controller, a script on it) it needs no login, as rotctld's `S` on the
  // loopback needs none. From the LAN it needs one, like every other action, and so does a
  // request a local reverse proxy (nginx, Caddy) passes on from anywhere (docs/remote.md).
  if (request.path != "/api/stop" || request.method != "POST" || request.forwarded) return false;
  const std::string& c = request.client;
  return c == "::1" || c.rfind("127.", 0) == 0 || c.rfind("::ffff:127.", 0) == 0;
}

bool WebApi::has_session(const linux_os::HttpRequest& request) const {
  if (request.authorization.rfind("Bearer ", 0) == 0) {
    return auth_.bearer_ok(std::string_view(request.authorization).substr(7));
  }
  return auth_.csrf_of(cookie_value(request.cookie, "azt_session"), now_()).has_value();
}

void WebApi::login(const linux_os::HttpRequest& request, const Respond& respond) {
  if (!origin_matches(request)) {
    respond(error_reply(403, "cross-origin request refused"));
    return;
  }
  const json body = json::parse(request.body, nullptr, false);
  if (body.is_discarded() || !body.is_object() || !body.contains("password") ||
      !body["password"].is_string()) {
    respond(error_reply(400, "expected {\"password\": \"…\"}", "password"));
    return;
  }
  const auto ticket = auth_.begin_login(request.client, now_());
  if (ticket.outcome != WebAuth::LoginOutcome::Checking) {
    const bool busy = ticket.outcome == WebAuth::LoginOutcome::Busy;
    linux_os::HttpReply r =
        error_reply(busy ? 503 : 429, busy ? "busy checking other logins: try again"
                                           : "too many failed logins: try again later");
    r.headers.emplace_back("Retry-After",
                           std::to_string(static_cast<long>(std::ceil(ticket.retry_after_s))));
    respond(r);
    return;
  }
  // Argon2id takes ~0.1 s and 64 MiB: on the worker, never on the loop.
  auto matched = std::make_shared<bool>(false);
  offload_(
      [matched, hash = auth_.password_hash(), password = body["password"].get<std::string>()] {
        *matched = !hash.empty() && verify_password(hash, password);
      },
      [this, matched, client = request.client, respond] {
        const auto result = auth_.finish_login(client, *matched, now_());
        if (result.outcome != WebAuth::LoginOutcome::Ok) {
          respond(error_reply(401, "wrong password", "password"));
          return;
        }
        linux_os::HttpReply r = json_reply(200, json{{"ok", true}, {"csrf", result.csrf}});
        r.headers.emplace_back(
            "Set-Cookie", "azt_session=" + result.session + "; HttpOnly; SameSite=Strict; Path=/");
        respond(r);
      });
}

void WebApi::handle_action(linux_os::HttpRequest& request, const Respond& respond) {
  if (request.path == "/api/login" && request.method == "POST") {
    login(request, respond);
    return;
  }
  if (is_local_stop(request)) {
    if (!origin_matches(request)) {
      respond(error_reply(403, "cross-origin request refused"));
      return;
    }
  } else if (auto refusal = authorize(request)) {
    respond(*refusal);
    return;
  }
  if (request.path == "/api/logout" && request.method == "POST") {
    auth_.logout(cookie_value(request.cookie, "azt_session"));
    linux_os::HttpReply r = json_reply(200, json{{"ok", true}});
    r.headers.emplace_back("Set-Cookie",
                           "azt_session=; HttpOnly; SameSite=Strict; Path=/; Max-Age=0");
    respond(r);
    return;
  }
  if (handle_account(request, respond)) return;
  if (request.path == "/api/software/update" && request.method == "POST") {
    if (software_ == nullptr) {
      respond(error_reply(404, "no software updates here"));
      return;
    }
    const auto* upload = dynamic_cast<const PackageUpload*>(request.streamed_body.get());
    if (upload == nullptr) {
      respond(error_reply(409, "software updates are not set up here"));
      return;
    }
    software_->receive(*upload, answer(respond));
    return;
  }
  if (request.path == "/api/satellites/elements" && request.method == "POST") {
    model_.upload_elements(std::move(request.body), "console " + request.client, answer(respond));
    return;
  }
  if (request.path == "/api/calibration/log" && request.method == "POST") {
    model_.import_scan_log(std::move(request.body), "console " + request.client, answer(respond));
    return;
  }
  const bool is_config = request.path.rfind("/api/config/", 0) == 0;
  if (is_config != (request.method == "PUT") || request.method == "DELETE" ||
      request.path.rfind("/api/", 0) != 0) {
    respond(error_reply(request.path.rfind("/api/", 0) == 0 ? 405 : 404,
                        request.method + " " + request.path + " is not an action"));
    return;
  }
  json body = json::object();
  if (!request.body.empty()) {
    body = json::parse(request.body, nullptr, false);
    if (body.is_discarded() || !body.is_object()) {
      respond(error_reply(400, "the body must be a JSON object"));
      return;
    }
  }
  model_.act(request.path.substr(5), body, "console " + request.client, answer(respond));
}

}  // namespace azt::app
