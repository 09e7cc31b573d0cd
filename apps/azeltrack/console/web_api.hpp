#pragma once
// The console's HTTP API (docs/web-api.md): routing, authentication, Origin and Host checks,
// JSON in and out. What the station shows and does is behind ConsoleModel, which the daemon
// implements; this file decides only who may ask and how the answer is shaped.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/off_loop.hpp"
#include "console/web_auth.hpp"
#include "console/web_server.hpp"

namespace azt::app {

/// A refused action: HTTP status (400 for a bad value, 409 for "not now"), the field at fault.
class ApiError : public std::runtime_error {
 public:
  ApiError(unsigned status, std::string field, const std::string& message)
      : std::runtime_error(message), status_(status), field_(std::move(field)) {}
  [[nodiscard]] unsigned status() const { return status_; }
  [[nodiscard]] const std::string& field() const { return field_; }

 private:
  unsigned status_;
  std::string field_;
};

/// What an action came to: the fields to add to {"ok": true}, or its refusal.
struct ActResult {
  nlohmann::json fields = nlohmann::json::object();
  std::optional<ApiError> error;
};
using ActDone = std::function<void(ActResult)>;

class ConsoleModel {
 public:
  ConsoleModel() = default;
  ConsoleModel(const ConsoleModel&) = delete;
  ConsoleModel& operator=(const ConsoleModel&) = delete;
  virtual ~ConsoleModel() = default;

  virtual nlohmann::json state() = 0;
  virtual nlohmann::json config() = 0;
  virtual nlohmann::json targets() = 0;
  virtual nlohmann::json sky(double hours) = 0;
  /// `action` is the route after "/api/" ("target", "stop", "config/tilt", …); `source` names
  /// who asked ("console 192.168.1.20") for the station's record of commands. Throws ApiError
  /// for a refusal known at once; otherwise calls `done` exactly once, at once or later (a save
  /// finishes off the event loop), always on the loop's thread.
  virtual void act(const std::string& action, const nlohmann::json& body, const std::string& source,
                   ActDone done) = 0;
};

struct WebApiConfig {
  /// Host header names accepted besides IP literals and "localhost" (DNS-rebinding defence).
  std::vector<std::string> allowed_hosts;
};

class WebApi {
 public:
  using Clock = std::function<double()>;  ///< monotonic seconds
  using Respond = WebServer::Respond;

  WebApi(ConsoleModel& model, WebAuth& auth, WebApiConfig config, Clock now,
         Offload offload = run_inline)
      : model_(model),
        auth_(auth),
        config_(std::move(config)),
        now_(std::move(now)),
        offload_(std::move(offload)) {}

  /// Answers `request` through `respond`, exactly once: at once, or later for what runs off the
  /// loop (a login's password check, a save). Never throws.
  void handle(const WebRequest& request, const Respond& respond);
  /// The WebSocket upgrade: nullopt accepts it.
  std::optional<WebReply> check_upgrade(const WebRequest& request) const;
  /// Whether the request carries a valid session cookie or bearer token (no CSRF check): a
  /// logged-in console's connections are admitted where anonymous ones are capped.
  [[nodiscard]] bool has_session(const WebRequest& request) const;

 private:
  WebReply handle_get(const WebRequest& request);
  void handle_action(const WebRequest& request, const Respond& respond);
  void login(const WebRequest& request, const Respond& respond);
  /// nullopt when the request may act; otherwise the 401/403 to send.
  std::optional<WebReply> authorize(const WebRequest& request) const;
  [[nodiscard]] bool host_allowed(const std::string& host) const;
  [[nodiscard]] static bool origin_matches(const WebRequest& request);

  ConsoleModel& model_;
  WebAuth& auth_;
  WebApiConfig config_;
  Clock now_;
  Offload offload_;
};

/// The cookie's value named `name` in a Cookie header, "" when absent.
std::string cookie_value(const std::string& cookie_header, const std::string& name);

}  // namespace azt::app
