#include "web_server.hpp"

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <chrono>
#include <optional>

namespace azt::app {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

constexpr std::size_t kMaxBodyBytes = std::size_t{64} * 1024;
constexpr std::size_t kMaxHeaderBytes = std::size_t{8} * 1024;
constexpr std::size_t kMaxWsMessageBytes = std::size_t{4} * 1024;
constexpr auto kIdleTimeout = std::chrono::seconds(30);

class WsSession;
class HttpSession;

}  // namespace

struct WebServer::Shared {
  Handler handler;
  UpgradeCheck upgrade_check;
  StateText state;
  Log log;
  std::vector<std::weak_ptr<HttpSession>> http;
  std::vector<std::weak_ptr<WsSession>> ws;
  bool closed = false;

  [[nodiscard]] std::size_t live_connections() const;
};

namespace {

std::string header(const http::request<http::string_body>& req, http::field f) {
  const auto it = req.find(f);
  return it == req.end() ? std::string() : std::string(it->value());
}

WebRequest to_web_request(const http::request<http::string_body>& req, const std::string& peer) {
  WebRequest r;
  r.method = std::string(req.method_string());
  const std::string target(req.target());
  const auto q = target.find('?');
  r.path = target.substr(0, q);
  if (q != std::string::npos) r.query = target.substr(q + 1);
  r.body = req.body();
  r.origin = header(req, http::field::origin);
  r.host = header(req, http::field::host);
  r.cookie = header(req, http::field::cookie);
  r.authorization = header(req, http::field::authorization);
  if (const auto it = req.find("X-CSRF-Token"); it != req.end()) r.csrf = std::string(it->value());
  r.client = peer;
  r.websocket = websocket::is_upgrade(req);
  return r;
}

http::response<http::string_body> to_response(const WebReply& reply, unsigned version,
                                              bool keep_alive) {
  http::response<http::string_body> res{static_cast<http::status>(reply.status), version};
  res.set(http::field::server, "azeltrack");
  res.set(http::field::content_type, reply.content_type);
  // The console is self-contained: nothing may frame it, load foreign code, or sniff types.
  res.set(http::field::cache_control, "no-store");
  res.set("X-Content-Type-Options", "nosniff");
  res.set("X-Frame-Options", "DENY");
  res.set("Content-Security-Policy",
          "default-src 'self'; connect-src 'self'; img-src 'self' data:; style-src 'self'; "
          "script-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'self'");
  res.set("Referrer-Policy", "no-referrer");
  for (const auto& [name, value] : reply.headers) res.set(name, value);
  res.body() = reply.body;
  res.keep_alive(keep_alive);
  res.prepare_payload();
  return res;
}

WebReply plain_error(unsigned status, const std::string& message) {
  return WebReply{status, "application/json", "{\"error\":\"" + message + "\"}", {}};
}

/// One WebSocket client: receives the pushed state; what it sends is read and ignored (a read
/// must be pending to notice a close). A slow client keeps only the newest frame pending.
class WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(tcp::socket socket, std::shared_ptr<WebServer::Shared> shared)
      : ws_(std::move(socket)), shared_(std::move(shared)) {}

  void start(const http::request<http::string_body>& req) {
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.read_message_max(kMaxWsMessageBytes);
    ws_.async_accept(req, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return;
      self->shared_->ws.push_back(self);
      self->push(std::make_shared<const std::string>(self->shared_->state()));
      self->read();
    });
  }

  void push(std::shared_ptr<const std::string> text) {
    if (closed_) return;
    if (writing_) {
      next_ = std::move(text);  // replaces an older pending frame: state is idempotent
      return;
    }
    writing_ = true;
    current_ = std::move(text);
    ws_.text(true);
    ws_.async_write(
        asio::buffer(*current_),
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_written(ec); });
  }

  void close() {
    if (closed_) return;
    closed_ = true;
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }

 private:
  void read() {
    ws_.async_read(in_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) {
        self->close();
        return;
      }
      self->in_.consume(self->in_.size());
      self->read();
    });
  }

  void on_written(beast::error_code ec) {
    writing_ = false;
    current_.reset();
    if (ec) {
      close();
      return;
    }
    if (next_) push(std::exchange(next_, nullptr));
  }

  websocket::stream<beast::tcp_stream> ws_;
  std::shared_ptr<WebServer::Shared> shared_;
  beast::flat_buffer in_;
  std::shared_ptr<const std::string> current_;
  std::shared_ptr<const std::string> next_;
  bool writing_ = false;
  bool closed_ = false;
};

/// One HTTP connection: requests in order, keep-alive, an upgrade hands the socket to WsSession.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket socket, std::shared_ptr<WebServer::Shared> shared, std::string peer)
      : stream_(std::move(socket)), shared_(std::move(shared)), peer_(std::move(peer)) {}

  void start() { read(); }

  void close() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
    stream_.socket().close(ignored);
  }

  [[nodiscard]] bool open() const { return stream_.socket().is_open(); }

 private:
  void read() {
    parser_.emplace();
    parser_->body_limit(kMaxBodyBytes);
    parser_->header_limit(kMaxHeaderBytes);
    stream_.expires_after(kIdleTimeout);
    http::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
  }

  void on_read(beast::error_code ec) {
    if (shared_->closed) return;
    if (ec == http::error::body_limit) {
      reply(plain_error(413, "request body over 64 KiB"), 11, false);
      return;
    }
    if (ec) {
      close();
      return;
    }
    http::request<http::string_body> req = parser_->release();
    const WebRequest request = to_web_request(req, peer_);
    if (request.websocket && request.path == "/ws") {
      if (auto refusal = shared_->upgrade_check(request)) {
        reply(*refusal, req.version(), false);
        return;
      }
      stream_.expires_never();
      auto ws = std::make_shared<WsSession>(stream_.release_socket(), shared_);
      ws->start(req);
      return;
    }
    reply(shared_->handler(request), req.version(), req.keep_alive());
  }

  void reply(const WebReply& reply, unsigned version, bool keep_alive) {
    auto res = std::make_shared<http::response<http::string_body>>(
        to_response(reply, version, keep_alive));
    http::async_write(
        stream_, *res,
        [self = shared_from_this(), res, keep_alive](beast::error_code ec, std::size_t) {
          if (ec || !keep_alive || self->shared_->closed) {
            self->close();
            return;
          }
          self->read();
        });
  }

  beast::tcp_stream stream_;
  std::shared_ptr<WebServer::Shared> shared_;
  std::string peer_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

}  // namespace

std::size_t WebServer::Shared::live_connections() const {
  std::size_t n = 0;
  for (const auto& w : http) {
    if (const auto s = w.lock(); s && s->open()) ++n;
  }
  for (const auto& w : ws) n += w.expired() ? 0U : 1U;
  return n;
}

WebServer::WebServer(asio::io_context& io, std::shared_ptr<Shared> shared, double push_period_s)
    : acceptor_(io),
      push_timer_(io),
      push_period_(std::chrono::duration_cast<asio::steady_timer::duration>(
          std::chrono::duration<double>(push_period_s))),
      shared_(std::move(shared)) {}

WebServer::~WebServer() { close(); }

Result<std::unique_ptr<WebServer>> WebServer::open(asio::io_context& io,
                                                   const std::string& bind_address,
                                                   unsigned short port, Handler handler,
                                                   UpgradeCheck upgrade_check, StateText state,
                                                   double push_period_s, Log log) {
  auto shared = std::make_shared<Shared>();
  shared->handler = std::move(handler);
  shared->upgrade_check = std::move(upgrade_check);
  shared->state = std::move(state);
  shared->log = std::move(log);
  std::unique_ptr<WebServer> server(new WebServer(io, shared, push_period_s));
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(bind_address, ec);
  if (ec) return fail("web: bind address '" + bind_address + "' is not an IP address");
  const tcp::endpoint endpoint(address, port);
  const auto where = "web on " + bind_address + ":" + std::to_string(port);
  if (server->acceptor_.open(endpoint.protocol(), ec); ec) return fail(where + ": " + ec.message());
  server->acceptor_.set_option(tcp::acceptor::reuse_address(true), ec);
  if (server->acceptor_.bind(endpoint, ec); ec) return fail(where + ": " + ec.message());
  if (server->acceptor_.listen(asio::socket_base::max_listen_connections, ec); ec) {
    return fail(where + ": " + ec.message());
  }
  server->accept_next();
  server->arm_push();
  return server;
}

unsigned short WebServer::port() const {
  boost::system::error_code ec;
  const auto endpoint = acceptor_.local_endpoint(ec);
  return ec ? 0 : endpoint.port();
}

std::size_t WebServer::websockets() const {
  std::size_t n = 0;
  for (const auto& w : shared_->ws) n += w.expired() ? 0U : 1U;
  return n;
}

void WebServer::close() {
  if (shared_->closed) return;
  shared_->closed = true;
  boost::system::error_code ignored;
  acceptor_.close(ignored);
  push_timer_.cancel();
  for (auto& w : shared_->http) {
    if (auto s = w.lock()) s->close();
  }
  for (auto& w : shared_->ws) {
    if (auto s = w.lock()) s->close();
  }
}

void WebServer::accept_next() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted || shared_->closed) return;
    if (!ec) {
      boost::system::error_code peer_ec;
      const auto peer = socket.remote_endpoint(peer_ec);
      std::erase_if(shared_->http, [](const auto& w) { return w.expired(); });
      std::erase_if(shared_->ws, [](const auto& w) { return w.expired(); });
      if (shared_->live_connections() >= kMaxConnections) {
        if (shared_->log) shared_->log("web: refused a connection: too many open");
        socket.close(peer_ec);
      } else {
        socket.set_option(tcp::no_delay(true), peer_ec);
        auto session = std::make_shared<HttpSession>(
            std::move(socket), shared_, peer_ec ? std::string("?") : peer.address().to_string());
        shared_->http.push_back(session);
        session->start();
      }
    }
    accept_next();
  });
}

void WebServer::arm_push() {
  push_timer_.expires_after(push_period_);
  push_timer_.async_wait([this](boost::system::error_code ec) {
    if (ec || shared_->closed) return;
    broadcast();
    arm_push();
  });
}

void WebServer::push_now() {
  if (!shared_->closed) broadcast();
}

void WebServer::broadcast() {
  std::erase_if(shared_->ws, [](const auto& w) { return w.expired(); });
  if (shared_->ws.empty()) return;
  // One serialisation per push, shared by every client.
  const auto text = std::make_shared<const std::string>(shared_->state());
  for (auto& w : shared_->ws) {
    if (auto s = w.lock()) s->push(text);
  }
}

}  // namespace azt::app
