#include "console/console_server.hpp"

#include "common/own_command.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

bool is_loopback(const std::string& bind) {
  boost::system::error_code ec;
  const auto address = boost::asio::ip::make_address(bind, ec);
  return !ec && address.is_loopback();
}

/// The password hash to use: the configured one, or a new one saved through the store.
std::string ensure_password(ConsoleParts& parts,
                            const std::function<void(const std::string&)>& log) {
  const WebConfig& web = parts.config.web;
  if (!web.password_hash.empty()) return web.password_hash;
  if (!is_loopback(web.bind)) {
    throw UsageError("[web] bind = \"" + web.bind +
                     "\" serves the network but no password is set: run `" +
                     password_command(parts.store.path()) + "` first");
  }
  const std::string password = random_password();
  std::string hash = hash_password(password);
  auto saved = parts.store.update([&hash](toml::table& root) {
    if (!root.contains("web")) root.insert("web", toml::table{});
    root["web"].as_table()->insert_or_assign("password_hash", hash);
  });
  if (!saved)
    throw UsageError("[web] cannot save the generated password: " + saved.error().message);
  parts.config.web.password_hash = hash;
  log("web console password (shown once): " + password + "; change it with `" +
      password_command(parts.store.path()) + "`");
  return hash;
}

}  // namespace

ConsoleServer::ConsoleServer(boost::asio::io_context& io, ConsoleParts parts,
                             const std::function<void(const std::string&)>& log,
                             SoftwareUpdates::Config software) {
  const WebConfig web = parts.config.web;
  std::vector<ApiToken> tokens;
  for (const WebToken& t : web.tokens) tokens.push_back({t.label, t.sha256, t.created_utc, false});
  if (!web.api_token_sha256.empty()) {
    tokens.push_back({"[web] api_token_sha256", web.api_token_sha256, "", true});
  }
  auth_ = std::make_unique<WebAuth>(WebAuth::Config{ensure_password(parts, log), tokens});
  std::function<double()> now = parts.monotonic_s;
  Offload offload = parts.offload;
  software_ = std::make_unique<SoftwareUpdates>(std::move(software), offload, parts.unix_s);
  console_ = std::make_unique<DaemonConsole>(std::move(parts));
  api_ = std::make_unique<WebApi>(*console_, *auth_, WebApiConfig{web.allowed_hosts}, now,
                                  std::move(offload));
  api_->serve_software(*software_);
  linux_os::HttpServer::Callbacks callbacks;
  callbacks.handler = [this](linux_os::HttpRequest r,
                             const linux_os::HttpServer::Respond& respond) {
    const bool change = r.method != "GET" && r.method != "HEAD";
    api_->handle(std::move(r), [this, change, respond](linux_os::HttpReply reply) {
      // A change made here reaches every open console now, not at the next periodic push.
      if (change && reply.status == 200 && server_) server_->push_now();
      respond(std::move(reply));
    });
  };
  callbacks.upgrade_check = [this](const linux_os::HttpRequest& r) {
    return api_->check_upgrade(r);
  };
  callbacks.has_session = [this](const linux_os::HttpRequest& r) { return api_->has_session(r); };
  callbacks.body_limit = [this](const linux_os::HttpRequest& r) { return api_->body_allowance(r); };
  callbacks.state = [this] {
    return console_->state().dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  callbacks.log = log;
  auto server = linux_os::HttpServer::open(io, web.bind, web.port, std::move(callbacks), 0.2);
  if (!server) throw UsageError("[web]: " + server.error().message);
  server_ = std::move(server).value();
}

}  // namespace azt::app
