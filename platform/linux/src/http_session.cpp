#include "http_session.hpp"

#include <chrono>
#include <cstdint>
#include <exception>
#include <limits>
#include <utility>

#include "azt/linux/http_request.hpp"
#include "azt/util/quote.hpp"
#include "azt/util/valid_utf8.hpp"
#include "websocket_session.hpp"

namespace azt::linux_os::web {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

namespace {

constexpr std::size_t kMaxHeaderBytes = std::size_t{8} * 1024;
constexpr auto kIdleTimeout = std::chrono::seconds(30);
// A refused upload's body is read and dropped for at most this long and this much.
constexpr auto kDrainTimeout = std::chrono::seconds(60);
constexpr std::size_t kMaxDrainBytes = std::size_t{128} * 1024 * 1024;
// A streamed body's chunk: the most of it in memory at once.
constexpr std::size_t kChunkBytes = std::size_t{128} * 1024;

}  // namespace

HttpSession::HttpSession(tcp::socket socket, std::shared_ptr<HttpServer::Shared> shared,
                         std::string address)
    : stream_(std::move(socket)), shared_(std::move(shared)) {
  peer = std::move(address);
}

void HttpSession::close() {
  beast::error_code ignored;
  stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
  stream_.socket().close(ignored);
}

// The head first: its route and credentials decide how large a body may follow (a logged-in
// operator's package upload; 64 KiB for everything else), before any of it is read.
void HttpSession::read() {
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

void HttpSession::on_header(beast::error_code ec) {
  if (ec || shared_->closed) {
    on_read(ec);
    return;
  }
  const auto& head = parser_->get();
  HttpServer::BodyAllowance allowance;
  if (shared_->callbacks.body_limit) {
    allowance = shared_->callbacks.body_limit(to_http_request(head.base(), peer));
  }
  if (allowance.refusal) {
    refuse_and_drain(*allowance.refusal, head.version());
    return;
  }
  hold_ = std::move(allowance.hold);
  sink_ = std::move(allowance.sink);
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
    stream_.expires_after(kIdleTimeout + std::chrono::seconds(bytes / (std::uint64_t{64} * 1024)));
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
void HttpSession::refuse_and_drain(const HttpReply& refusal, unsigned version) {
  hold_.reset();
  sink_.reset();
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

void HttpSession::drain(std::size_t dropped) {
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
void HttpSession::continue_then_read_body(unsigned version) {
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

void HttpSession::read_body() {
  if (sink_) {
    // The head is read and the body not begun: Beast lets the parser change its body type now.
    streaming_.emplace(std::move(*parser_));
    parser_.reset();
    read_chunk();
    return;
  }
  http::async_read(
      stream_, buffer_, *parser_,
      [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
}

bool HttpSession::answered_read_error(beast::error_code ec) {
  if (ec == http::error::body_limit) {
    reply(plain_error(413, "request body too large"), 11, false);
  } else if (ec == http::error::header_limit) {
    reply(plain_error(431, "request headers over 8 KiB"), 11, false);
  } else if (ec) {
    close();
  }
  return static_cast<bool>(ec);
}

void HttpSession::on_read(beast::error_code ec) {
  if (shared_->closed || answered_read_error(ec)) return;
  StringRequest req = parser_->release();
  // The body moves, never copied: a copy of a large body on the loop would stall it.
  std::string body = std::exchange(req.body(), std::string());
  HttpRequest request = to_http_request(req.base(), peer);
  request.body = std::move(body);
  guarded(request.method + " " + quote(request.path), [&] {
    note_session(request);
    if (request.websocket && request.path == "/ws") {
      upgrade(req, request);
      return;
    }
    dispatch(std::move(request), req.version(), req.keep_alive());
  });
}

void HttpSession::read_chunk() {
  chunk_.resize(kChunkBytes);
  auto& body = streaming_->get().body();
  body.data = chunk_.data();
  body.size = chunk_.size();
  http::async_read(
      stream_, buffer_, *streaming_,
      [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_chunk(ec); });
}

void HttpSession::on_chunk(beast::error_code ec) {
  if (ec == http::error::need_buffer) ec = {};  // the chunk is full: Beast's incremental read
  if (shared_->closed || answered_read_error(ec)) return;
  chunk_.resize(chunk_.size() - streaming_->get().body().size);
  const bool last = streaming_->is_done();
  guarded("a streamed request body", [&] {
    sink_->write(std::exchange(chunk_, std::string()),
                 [self = shared_from_this(), last](const std::optional<HttpReply>& refusal) {
                   self->on_chunk_taken(last, refusal);
                 });
  });
}

void HttpSession::on_chunk_taken(bool last, const std::optional<HttpReply>& refusal) {
  if (shared_->closed || !open()) return;
  if (refusal) {
    refuse_and_drain(*refusal, streaming_->get().version());
  } else if (last) {
    finish_streamed();
  } else {
    read_chunk();
  }
}

void HttpSession::finish_streamed() {
  const auto& req = streaming_->get();
  HttpRequest request = to_http_request(req.base(), peer);
  request.streamed_body = std::exchange(sink_, nullptr);
  const unsigned version = req.version();
  const bool keep_alive = req.keep_alive();
  streaming_.reset();
  guarded(request.method + " " + quote(request.path), [&] {
    note_session(request);
    dispatch(std::move(request), version, keep_alive);
  });
}

void HttpSession::guarded(const std::string& what, const std::function<void()>& step) {
  try {
    step();
  } catch (const std::exception& e) {
    shared_->log("web: " + peer + " " + what +
                 ": internal error, connection closed: " + valid_utf8(e.what()));
    close();
  }
}

void HttpSession::note_session(const HttpRequest& request) {
  if (!has_session && shared_->callbacks.has_session(request)) has_session = true;
}

void HttpSession::dispatch(HttpRequest request, unsigned version, bool keep_alive) {
  shared_->callbacks.handler(std::move(request),
                             [self = shared_from_this(), version, keep_alive](const HttpReply& r) {
                               self->reply(r, version, keep_alive);
                             });
}

void HttpSession::upgrade(const StringRequest& req, const HttpRequest& request) {
  if (auto refusal = shared_->callbacks.upgrade_check(request)) {
    reply(*refusal, req.version(), false);
    return;
  }
  if (!has_session && shared_->anonymous_websockets() >= HttpServer::kMaxAnonymousWebSockets) {
    reply(plain_error(503, "too many live views without a login: log in to get one"), req.version(),
          false);
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

void HttpSession::reply(const HttpReply& reply, unsigned version, bool keep_alive) {
  hold_.reset();  // answered: the handler's slot is free for the next request
  sink_.reset();
  auto res =
      std::make_shared<http::response<http::string_body>>(to_response(reply, version, keep_alive));
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

}  // namespace azt::linux_os::web
