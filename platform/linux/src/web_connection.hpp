#pragma once
// What the console's transport (http_server.cpp) shares with its connections
// (http_session.cpp, websocket_session.cpp): the accounting every connection is in, and the
// reply as it goes on the wire. Private to the transport.

#include <boost/beast/http.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "azt/linux/http_server.hpp"

namespace azt::linux_os {

namespace web {
class WsSession;
}

/// What the server's accounting knows of every connection, HTTP or WebSocket.
class WebConnection {
 public:
  WebConnection() = default;
  WebConnection(const WebConnection&) = delete;
  WebConnection& operator=(const WebConnection&) = delete;
  virtual ~WebConnection() = default;
  virtual void close() = 0;
  [[nodiscard]] virtual bool open() const = 0;

  std::string peer;          ///< the client's address, no port
  bool has_session = false;  ///< a request on it showed a valid session: never evicted
  bool websocket = false;
};

struct HttpServer::Shared {
  Callbacks callbacks;
  std::vector<std::weak_ptr<WebConnection>> connections;  ///< oldest first
  std::vector<std::weak_ptr<web::WsSession>> ws;
  bool closed = false;

  void prune();
  [[nodiscard]] std::size_t live();
  /// Open connections for which `which` holds.
  [[nodiscard]] std::size_t count(const std::function<bool(const WebConnection&)>& which);
  [[nodiscard]] std::size_t from(const std::string& peer);
  [[nodiscard]] std::size_t websockets();
  [[nodiscard]] std::size_t anonymous_websockets();
  /// Closes the oldest connection without a session; false if every one has a session.
  bool evict_one_anonymous();
  void log(const std::string& line) const {
    if (callbacks.log) callbacks.log(line);
  }
};

namespace web {

/// `reply` as sent, with the console's security headers.
boost::beast::http::response<boost::beast::http::string_body> to_response(const HttpReply& reply,
                                                                          unsigned version,
                                                                          bool keep_alive);

/// For the transport's own refusals: `message` is a constant of the transport (no quoting
/// needed).
HttpReply plain_error(unsigned status, const std::string& message);

}  // namespace web
}  // namespace azt::linux_os
