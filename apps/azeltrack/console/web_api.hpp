#pragma once
// The console's HTTP API (docs/web-api.md): routing, authentication, Origin and Host checks,
// JSON in and out. What the station shows and does is behind ConsoleModel, which the daemon
// implements; this file decides only who may ask and how the answer is shaped.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/linux/http_server.hpp"
#include "common/off_loop.hpp"
#include "console/console_model.hpp"
#include "console/software_updates.hpp"
#include "console/web_auth.hpp"

namespace azt::app {

struct WebApiConfig {
  /// Host header names accepted besides IP literals and "localhost" (DNS-rebinding defence).
  std::vector<std::string> allowed_hosts;
};

class WebApi {
 public:
  using Clock = std::function<double()>;  ///< monotonic seconds
  using Respond = linux_os::HttpServer::Respond;

  WebApi(ConsoleModel& model, WebAuth& auth, WebApiConfig config, Clock now,
         Offload offload = run_inline)
      : model_(model),
        auth_(auth),
        config_(std::move(config)),
        now_(std::move(now)),
        offload_(std::move(offload)) {}

  /// Answers `request` through `respond`, exactly once: at once, or later for what runs off the
  /// loop (a login's password check, a save). Never throws. The request is taken by value: a
  /// package upload's body moves on to the software updates, never copied on the loop.
  void handle(linux_os::HttpRequest request, const Respond& respond);
  /// GET /api/software and POST /api/software/update (docs/packaging.md); without, both are 404.
  void serve_software(SoftwareUpdates& software) { software_ = &software; }
  /// What body the request whose head this is may send: a package upload from a logged-in
  /// console may be large; one without a login is answered 401 from its head; everything else
  /// is small (HttpServer::kMaxBodyBytes). One upload at a time, decided here from the head:
  /// while another is being received or stored, the next is answered 409 before its body is read
  /// (docs/reliability.md: eight 60 MiB uploads had all been read into memory first).
  [[nodiscard]] linux_os::HttpServer::BodyAllowance body_allowance(
      const linux_os::HttpRequest& head);
  /// An element file (POST /api/satellites/elements) is held whole: CelesTrak's `active` group
  /// as TLE is under 2 MB, as OMM JSON about 10 MB.
  static constexpr std::size_t kMaxElementUploadBytes = std::size_t{16} * 1024 * 1024;
  /// A scan log to import (POST /api/calibration/log): 25 000 rows of the export's columns.
  static constexpr std::size_t kMaxScanLogUploadBytes = std::size_t{4} * 1024 * 1024;
  /// The WebSocket upgrade: nullopt accepts it.
  std::optional<linux_os::HttpReply> check_upgrade(const linux_os::HttpRequest& request) const;
  /// Whether the request carries a valid session cookie or bearer token (no CSRF check): a
  /// logged-in console's connections are admitted where anonymous ones are capped.
  [[nodiscard]] bool has_session(const linux_os::HttpRequest& request) const;

 private:
  linux_os::HttpReply handle_get(const linux_os::HttpRequest& request);
  void handle_action(linux_os::HttpRequest& request, const Respond& respond);
  void login(const linux_os::HttpRequest& request, const Respond& respond);
  /// GET /api/software, answered off the loop; 404 when not served.
  void software_status(const Respond& respond);
  /// nullopt when the request may act; otherwise the 401/403 to send.
  std::optional<linux_os::HttpReply> authorize(const linux_os::HttpRequest& request) const;
  [[nodiscard]] bool host_allowed(const std::string& host) const;
  [[nodiscard]] static bool origin_matches(const linux_os::HttpRequest& request);
  /// POST /api/stop from a loopback address: allowed without a login.
  [[nodiscard]] static bool is_local_stop(const linux_os::HttpRequest& request);
  // The account (account_api.cpp), each after authorize(): the API tokens, the password, the
  // whole settings file. False: the request is none of them.
  bool handle_account(const linux_os::HttpRequest& request, const Respond& respond);
  void list_tokens(const Respond& respond) const;
  void create_token(const linux_os::HttpRequest& request, const Respond& respond);
  void revoke_token(const std::string& label, const Respond& respond);
  void change_password(const linux_os::HttpRequest& request, const Respond& respond);
  void import_file(const linux_os::HttpRequest& request, const Respond& respond);
  /// The running check takes the tokens just saved (`records`), the legacy one kept.
  void take_tokens(const nlohmann::json& records);
  /// The tokens' records as save_tokens takes them, `with` added or `without` left out.
  [[nodiscard]] nlohmann::json token_records(const std::optional<ApiToken>& with,
                                             const std::string& without) const;

  ConsoleModel& model_;
  WebAuth& auth_;
  WebApiConfig config_;
  Clock now_;
  Offload offload_;
  SoftwareUpdates* software_ = nullptr;
  /// The upload being received or stored: its connection holds the token until it is answered.
  std::weak_ptr<const void> upload_slot_;
  std::weak_ptr<const void> elements_slot_;  ///< one element upload read at a time
  std::weak_ptr<const void> scan_log_slot_;  ///< one scan log import read at a time
};

/// The cookie's value named `name` in a Cookie header, "" when absent.
std::string cookie_value(const std::string& cookie_header, const std::string& name);

}  // namespace azt::app
