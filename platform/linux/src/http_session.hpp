#pragma once
// One HTTP connection of the console: requests in order, keep-alive; the head first, whose route
// and credentials decide what body may follow (held whole up to a limit, streamed to the route's
// sink, or refused and drained); an upgrade hands the socket to a WsSession.

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "web_connection.hpp"

namespace azt::linux_os::web {

class HttpSession : public WebConnection, public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket socket, std::shared_ptr<HttpServer::Shared> shared,
              std::string address);

  void start() { read(); }
  void close() override;
  [[nodiscard]] bool open() const override { return stream_.socket().is_open(); }

 private:
  using StringRequest = boost::beast::http::request<boost::beast::http::string_body>;

  void read();
  void on_header(boost::beast::error_code ec);
  void refuse_and_drain(const HttpReply& refusal, unsigned version);
  void drain(std::size_t dropped);
  void continue_then_read_body(unsigned version);
  void read_body();
  void on_read(boost::beast::error_code ec);
  /// A read's error answered (413, 431) or the connection closed; false when there was none.
  bool answered_read_error(boost::beast::error_code ec);
  // A body streamed to the route's sink, one chunk in memory at a time.
  void read_chunk();
  void on_chunk(boost::beast::error_code ec);
  void on_chunk_taken(bool last, const std::optional<HttpReply>& refusal);
  void finish_streamed();
  /// Runs `step` (a handler's call); an exception from it closes this connection with a log
  /// line naming `what`, and the daemon and other clients carry on.
  void guarded(const std::string& what, const std::function<void()>& step);
  /// Marks this connection as logged in once a request on it shows a session (never evicted).
  void note_session(const HttpRequest& request);
  void dispatch(HttpRequest request, unsigned version, bool keep_alive);
  void upgrade(const StringRequest& req, const HttpRequest& request);
  void reply(const HttpReply& reply, unsigned version, bool keep_alive);

  boost::beast::tcp_stream stream_;
  std::shared_ptr<HttpServer::Shared> shared_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::buffer_body>> streaming_;
  std::shared_ptr<HttpBodySink> sink_;  ///< the route's, while its body arrives
  std::string chunk_;
  std::shared_ptr<const void> hold_;  ///< the body allowance's token, until answered
};

}  // namespace azt::linux_os::web
