#pragma once
// One WebSocket client of the console (/ws): receives the pushed state; what it sends is read
// and ignored (a read must be pending to notice a close). A slow client keeps only the newest
// frame pending: state is idempotent, so older frames are dropped, never queued.

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <memory>
#include <string>

#include "web_connection.hpp"

namespace azt::linux_os::web {

class WsSession : public WebConnection, public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(boost::asio::ip::tcp::socket socket, std::shared_ptr<HttpServer::Shared> shared);

  /// Completes the handshake `req` asked for, then pushes the state at once.
  template <class Body>
  void start(const boost::beast::http::request<Body>& req) {
    prepare();
    ws_.async_accept(req, [self = shared_from_this()](boost::beast::error_code ec) {
      if (!ec) self->on_accepted();
    });
  }

  void push(std::shared_ptr<const std::string> text);
  void close() override;
  [[nodiscard]] bool open() const override { return !closed_; }

 private:
  void prepare();
  void on_accepted();
  void read();
  void on_written(boost::beast::error_code ec);

  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  std::shared_ptr<HttpServer::Shared> shared_;
  boost::beast::flat_buffer in_;
  std::shared_ptr<const std::string> current_;
  std::shared_ptr<const std::string> next_;
  bool writing_ = false;
  bool closed_ = false;
};

}  // namespace azt::linux_os::web
