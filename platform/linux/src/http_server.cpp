#include "azt/linux/http_server.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "http_session.hpp"
#include "tcp_listen.hpp"
#include "web_connection.hpp"
#include "websocket_session.hpp"

namespace azt::linux_os {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

using web::HttpSession;
using web::WsSession;

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
