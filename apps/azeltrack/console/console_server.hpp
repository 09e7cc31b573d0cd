#pragma once
// The web console as one piece for the daemon: authentication, the API over the daemon's parts,
// and the HTTP/WebSocket server, on the daemon's io_context.

#include <functional>
#include <memory>
#include <string>

#include "azt/linux/http_server.hpp"
#include "console/daemon_console.hpp"
#include "console/software_updates.hpp"
#include "console/web_api.hpp"
#include "console/web_auth.hpp"

namespace azt::app {

class ConsoleServer {
 public:
  /// Opens the server; throws UsageError naming [web] when it cannot (a port in use, a LAN bind
  /// address without a password). With no password configured on a loopback address, one is
  /// generated, its hash saved through the store, and the password given to `log` once.
  /// `software`: the Software page's version and update paths (SoftwareUpdates::Config).
  ConsoleServer(boost::asio::io_context& io, ConsoleParts parts,
                const std::function<void(const std::string&)>& log,
                SoftwareUpdates::Config software);

  [[nodiscard]] unsigned short port() const { return server_->port(); }
  [[nodiscard]] std::size_t websockets() const { return server_->websockets(); }
  void close() { server_->close(); }
  /// The state changed outside the console (a PC program, a fault): push it now.
  void push_now() { server_->push_now(); }

 private:
  std::unique_ptr<WebAuth> auth_;
  std::unique_ptr<DaemonConsole> console_;
  std::unique_ptr<SoftwareUpdates> software_;
  std::unique_ptr<WebApi> api_;
  std::unique_ptr<linux_os::HttpServer> server_;
};

}  // namespace azt::app
