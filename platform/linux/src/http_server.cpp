#include "azt/linux/http_server.hpp"

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

#include "azt/linux/http_request.hpp"
#include "azt/util/quote.hpp"
#include "azt/util/valid_utf8.hpp"
#include "tcp_listen.hpp"

namespace azt::linux_os {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

constexpr std::size_t kMaxHeaderBytes = std::size_t{8} * 1024;
constexpr std::size_t kMaxWsMessageBytes = std::size_t{4} * 1024;
constexpr auto kIdleTimeout = std::chrono::seconds(30);
// A refused upload's body is read and dropped for at most this long and this much.
constexpr auto kDrainTimeout = std::chrono::seconds(60);
constexpr std::size_t kMaxDrainBytes = std::size_t{128} * 1024 * 1024;

class WsSession;
class HttpSession;

}  // namespace

class WebConnection;

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
  std::vector<std::weak_ptr<WsSession>> ws;
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

namespace {

http::response<http::string_body> to_response(const HttpReply& reply, unsigned version,
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

/// For the transport's own refusals: `message` is a constant of this file (no quoting needed).
HttpReply plain_error(unsigned status, const std::string& message) {
  return HttpReply{status, "application/json", "{\"error\":\"" + message + "\"}", {}};
}

/// One WebSocket client: receives the pushed state; what it sends is read and ignored (a read
/// must be pending to notice a close). A slow client keeps only the newest frame pending.
class WsSession : public WebConnection, public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(tcp::socket socket, std::shared_ptr<HttpServer::Shared> shared)
      : ws_(std::move(socket)), shared_(std::move(shared)) {
    websocket = true;
  }

  void start(const http::request<http::string_body>& req) {
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.read_message_max(kMaxWsMessageBytes);
    ws_.async_accept(req, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return;
      self->shared_->ws.push_back(self);
      self->push(std::make_shared<const std::string>(self->shared_->callbacks.state()));
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

  void close() override {
    if (closed_) return;
    closed_ = true;
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }

  [[nodiscard]] bool open() const override { return !closed_; }

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
  std::shared_ptr<HttpServer::Shared> shared_;
  beast::flat_buffer in_;
  std::shared_ptr<const std::string> current_;
  std::shared_ptr<const std::string> next_;
  bool writing_ = false;
  bool closed_ = false;
};

/// One HTTP connection: requests in order, keep-alive, an upgrade hands the socket to WsSession.
class HttpSession : public WebConnection, public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket socket, std::shared_ptr<HttpServer::Shared> shared, std::string address)
      : stream_(std::move(socket)), shared_(std::move(shared)) {
    peer = std::move(address);
  }

  void start() { read(); }

  void close() override {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
    stream_.socket().close(ignored);
  }

  [[nodiscard]] bool open() const override { return stream_.socket().is_open(); }

 private:
  // The head first: its route and credentials decide how large a body may follow (a logged-in
  // operator's package upload; 64 KiB for everything else), before any of it is read.
  void read() {
    parser_.emplace();
    // Beast compares Content-Length with the limit as the head completes: no limit until
    // on_header has chosen one (it refuses a larger Content-Length before reading a byte).
    parser_->body_limit(std::numeric_limits<std::uint64_t>::max());
    parser_->header_limit(kMaxHeaderBytes);
    stream_.expires_after(kIdleTimeout);
    http::async_read_header(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
  }

  void on_header(beast::error_code ec) {
    if (ec || shared_->closed) {
      on_read(ec);
      return;
    }
    const auto& head = parser_->get();
    HttpServer::BodyAllowance allowance;
    if (shared_->callbacks.body_limit) {
      allowance = shared_->callbacks.body_limit(to_http_request(head, peer));
    }
    if (allowance.refusal) {
      refuse_and_drain(*allowance.refusal, head.version());
      return;
    }
    hold_ = std::move(allowance.hold);
    const std::size_t limit = allowance.max_bytes;
    const auto length = parser_->content_length();
    if (length && *length > limit) {
      reply(plain_error(413, "request body too large"), head.version(), false);
      return;
    }
    parser_->body_limit(limit);
    // An upload gets time to arrive over a slow link: the idle time and a second per 64 KiB.
    if (limit > HttpServer::kMaxBodyBytes) {
      const std::uint64_t bytes = length.value_or(limit);
      stream_.expires_after(kIdleTimeout +
                            std::chrono::seconds(bytes / (std::uint64_t{64} * 1024)));
    }
    if (beast::iequals(head[http::field::expect], "100-continue")) {
      continue_then_read_body(head.version());
      return;
    }
    read_body();
  }

  // A client that sends its body whatever the answer (most do, browsers among them) would find
  // the connection reset under it if it were closed with the body unread, and never read the
  // answer: the answer goes first, then what arrives is dropped until the client stops, up to
  // kMaxDrainBytes or kDrainTimeout, and the connection closes.
  void refuse_and_drain(const HttpReply& refusal, unsigned version) {
    auto res =
        std::make_shared<http::response<http::string_body>>(to_response(refusal, version, false));
    http::async_write(stream_, *res,
                      [self = shared_from_this(), res](beast::error_code ec, std::size_t) {
                        if (ec) {
                          self->close();
                          return;
                        }
                        beast::error_code ignored;
                        self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                        self->stream_.expires_after(kDrainTimeout);
                        self->drain(self->buffer_.size());
                      });
  }

  void drain(std::size_t dropped) {
    buffer_.clear();
    if (dropped > kMaxDrainBytes) {
      close();
      return;
    }
    stream_.async_read_some(
        buffer_.prepare(std::size_t{64} * 1024),
        [self = shared_from_this(), dropped](beast::error_code ec, std::size_t n) {
          if (ec) {
            self->close();
            return;
          }
          self->drain(dropped + n);
        });
  }

  /// curl and other clients wait for "100 Continue" before sending a large body (RFC 9110 §10.1.1).
  void continue_then_read_body(unsigned version) {
    auto res = std::make_shared<http::response<http::empty_body>>(http::status::continue_, version);
    http::async_write(stream_, *res,
                      [self = shared_from_this(), res](beast::error_code ec, std::size_t) {
                        if (ec) {
                          self->close();
                          return;
                        }
                        self->read_body();
                      });
  }

  void read_body() {
    http::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
  }

  void on_read(beast::error_code ec) {
    if (shared_->closed) return;
    if (ec == http::error::body_limit) {
      reply(plain_error(413, "request body too large"), 11, false);
      return;
    }
    if (ec == http::error::header_limit) {
      reply(plain_error(431, "request headers over 8 KiB"), 11, false);
      return;
    }
    if (ec) {
      close();
      return;
    }
    http::request<http::string_body> req = parser_->release();
    // The body moves, never copied: an upload is megabytes, a copy on the loop would stall it.
    std::string body = std::exchange(req.body(), std::string());
    HttpRequest request = to_http_request(req, peer);
    request.body = std::move(body);
    const std::string what = request.method + " " + quote(request.path);
    try {
      dispatch(req, std::move(request));
    } catch (const std::exception& e) {
      // One request's fault closes its connection; the daemon and other clients carry on.
      shared_->log("web: " + peer + " " + what +
                   ": internal error, connection closed: " + valid_utf8(e.what()));
      close();
    }
  }

  void dispatch(const http::request<http::string_body>& req, HttpRequest request) {
    if (!has_session && shared_->callbacks.has_session(request)) has_session = true;
    if (request.websocket && request.path == "/ws") {
      upgrade(req, request);
      return;
    }
    const unsigned version = req.version();
    const bool keep_alive = req.keep_alive();
    shared_->callbacks.handler(
        std::move(request), [self = shared_from_this(), version, keep_alive](const HttpReply& r) {
          self->reply(r, version, keep_alive);
        });
  }

  void upgrade(const http::request<http::string_body>& req, const HttpRequest& request) {
    if (auto refusal = shared_->callbacks.upgrade_check(request)) {
      reply(*refusal, req.version(), false);
      return;
    }
    if (!has_session && shared_->anonymous_websockets() >= HttpServer::kMaxAnonymousWebSockets) {
      reply(plain_error(503, "too many live views without a login: log in to get one"),
            req.version(), false);
      return;
    }
    // Live views never take the slots that requests need: a STOP always finds a connection.
    if (shared_->websockets() >= HttpServer::kMaxWebSockets) {
      reply(plain_error(503, "too many live views open"), req.version(), false);
      return;
    }
    stream_.expires_never();
    auto ws = std::make_shared<WsSession>(stream_.release_socket(), shared_);
    ws->peer = peer;
    ws->has_session = has_session;
    shared_->connections.push_back(ws);
    ws->start(req);
  }

  void reply(const HttpReply& reply, unsigned version, bool keep_alive) {
    hold_.reset();  // answered: the handler's slot is free for the next request
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
  std::shared_ptr<HttpServer::Shared> shared_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<const void> hold_;  ///< the body allowance's token, until answered
};

}  // namespace

void HttpServer::Shared::prune() {
  std::erase_if(connections, [](const auto& w) {
    const auto c = w.lock();
    return !c || !c->open();
  });
  std::erase_if(ws, [](const auto& w) { return w.expired(); });
}

std::size_t HttpServer::Shared::live() {
  prune();
  return connections.size();
}

std::size_t HttpServer::Shared::count(const std::function<bool(const WebConnection&)>& which) {
  prune();
  return static_cast<std::size_t>(std::count_if(connections.begin(), connections.end(),
                                                [&](const auto& w) { return which(*w.lock()); }));
}

std::size_t HttpServer::Shared::from(const std::string& peer) {
  return count([&](const WebConnection& c) { return c.peer == peer; });
}

std::size_t HttpServer::Shared::websockets() {
  return count([](const WebConnection& c) { return c.websocket; });
}

std::size_t HttpServer::Shared::anonymous_websockets() {
  return count([](const WebConnection& c) { return c.websocket && !c.has_session; });
}

bool HttpServer::Shared::evict_one_anonymous() {
  prune();
  for (const auto& w : connections) {
    if (const auto c = w.lock(); !c->has_session) {
      log("web: closed the oldest connection without a login from " + c->peer + " to make room (" +
          std::to_string(kMaxConnections) + " open)");
      c->close();
      prune();
      return true;
    }
  }
  return false;
}

HttpServer::HttpServer(asio::io_context& io, std::shared_ptr<Shared> shared, double push_period_s)
    : acceptor_(io),
      push_timer_(io),
      push_period_(std::chrono::duration_cast<asio::steady_timer::duration>(
          std::chrono::duration<double>(push_period_s))),
      shared_(std::move(shared)) {}

HttpServer::~HttpServer() { close(); }

Result<std::unique_ptr<HttpServer>> HttpServer::open(asio::io_context& io,
                                                     const std::string& bind_address,
                                                     unsigned short port, Callbacks callbacks,
                                                     double push_period_s) {
  auto shared = std::make_shared<Shared>();
  shared->callbacks = std::move(callbacks);
  std::unique_ptr<HttpServer> server(new HttpServer(io, shared, push_period_s));
  if (auto ok = listen_on(server->acceptor_, "web", bind_address, port); !ok) return ok.error();
  server->accept_next();
  server->arm_push();
  return server;
}

unsigned short HttpServer::port() const { return bound_port(acceptor_); }

std::size_t HttpServer::websockets() const {
  std::size_t n = 0;
  for (const auto& w : shared_->ws) {
    const auto s = w.lock();
    n += s && s->open() ? 1U : 0U;
  }
  return n;
}

std::size_t HttpServer::connections() const { return shared_->live(); }

void HttpServer::close() {
  if (shared_->closed) return;
  shared_->closed = true;
  boost::system::error_code ignored;
  acceptor_.close(ignored);
  push_timer_.cancel();
  for (auto& w : shared_->connections) {
    if (auto c = w.lock()) c->close();
  }
}

void HttpServer::accept_next() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted || shared_->closed) return;
    if (!ec) admit(std::move(socket));
    accept_next();
  });
}

void HttpServer::admit(tcp::socket socket) {
  boost::system::error_code peer_ec;
  const auto peer = socket.remote_endpoint(peer_ec);
  const std::string address = peer_ec ? std::string("?") : peer.address().to_string();
  if (shared_->from(address) >= kMaxPerAddress) {
    shared_->log("web: refused a connection from " + address + ": " +
                 std::to_string(kMaxPerAddress) + " open from there");
    socket.close(peer_ec);
    return;
  }
  if (shared_->live() >= kMaxConnections && !shared_->evict_one_anonymous()) {
    shared_->log("web: refused a connection from " + address + ": " +
                 std::to_string(kMaxConnections) + " logged-in connections open");
    socket.close(peer_ec);
    return;
  }
  socket.set_option(tcp::no_delay(true), peer_ec);
  auto session = std::make_shared<HttpSession>(std::move(socket), shared_, address);
  shared_->connections.push_back(session);
  session->start();
}

void HttpServer::arm_push() {
  push_timer_.expires_after(push_period_);
  push_timer_.async_wait([this](boost::system::error_code ec) {
    if (ec || shared_->closed) return;
    broadcast();
    arm_push();
  });
}

void HttpServer::push_now() {
  if (!shared_->closed) broadcast();
}

void HttpServer::broadcast() {
  std::erase_if(shared_->ws, [](const auto& w) { return w.expired(); });
  if (shared_->ws.empty()) return;
  // One serialisation per push, shared by every client.
  const auto text = std::make_shared<const std::string>(shared_->callbacks.state());
  for (auto& w : shared_->ws) {
    if (auto s = w.lock()) s->push(text);
  }
}

}  // namespace azt::linux_os
