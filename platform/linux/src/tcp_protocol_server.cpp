#include "azt/linux/tcp_protocol_server.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <deque>

#include "tcp_listen.hpp"

namespace azt::linux_os {

namespace asio = boost::asio;
using asio::ip::tcp;

/// One client: reads feed the session; replies are queued and written one at a time.
class TcpProtocolServer::Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(tcp::socket socket, std::unique_ptr<proto::ProtocolSession> session,
             std::string client, std::string address, ConnectionLog log,
             const TcpServerLimits& limits, std::shared_ptr<std::size_t> live)
      : socket_(std::move(socket)),
        idle_(socket_.get_executor()),
        session_(std::move(session)),
        client_(std::move(client)),
        address_(std::move(address)),
        log_(std::move(log)),
        max_pending_(limits.max_pending_output),
        idle_timeout_s_(limits.idle_timeout_s),
        live_(std::move(live)) {
    ++*live_;
  }
  ~Connection() { --*live_; }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  void start() {
    arm_idle();
    read();
  }

  [[nodiscard]] const std::string& address() const { return address_; }
  [[nodiscard]] bool open() const { return !closed_; }

  void close(const std::string& why) {
    if (closed_) return;
    closed_ = true;
    idle_.cancel();
    boost::system::error_code ignored;
    socket_.shutdown(tcp::socket::shutdown_both, ignored);
    socket_.close(ignored);
    if (log_) log_(client_, "disconnected: " + why);
  }

 private:
  void read() {
    socket_.async_read_some(asio::buffer(buffer_),
                            [self = shared_from_this()](boost::system::error_code ec,
                                                        std::size_t n) { self->on_read(ec, n); });
  }

  void arm_idle() {
    if (idle_timeout_s_ <= 0.0) return;
    idle_.expires_after(std::chrono::duration_cast<asio::steady_timer::duration>(
        std::chrono::duration<double>(idle_timeout_s_)));
    idle_.async_wait(
        [self = weak_from_this(), timeout = idle_timeout_s_](boost::system::error_code ec) {
          const auto c = self.lock();
          if (ec || !c) return;
          c->close("silent for " + std::to_string(static_cast<long>(timeout)) + " s");
        });
  }

  void on_read(boost::system::error_code ec, std::size_t n) {
    if (closed_) return;
    if (ec) {
      close(ec == asio::error::eof ? "closed by the client" : ec.message());
      return;
    }
    arm_idle();
    std::string reply;
    try {
      reply = session_->feed(std::string_view(buffer_.data(), n));
    } catch (const std::exception& e) {
      // A fault in one session ends that session, never the daemon and its other clients.
      close(std::string("internal error, session closed: ") + e.what());
      return;
    }
    if (!reply.empty()) queue(std::move(reply));
    if (closed_) return;
    if (session_->finished()) {
      finishing_ = true;
      if (pending_.empty()) close("client quit");
      return;
    }
    read();
  }

  void queue(std::string bytes) {
    pending_bytes_ += bytes.size();
    if (pending_bytes_ > max_pending_) {
      // A client that sends but never reads would grow the queue without bound (slowloris).
      close("not reading its replies (" + std::to_string(pending_bytes_) + " bytes queued)");
      return;
    }
    pending_.push_back(std::move(bytes));
    if (pending_.size() == 1) write();
  }

  void write() {
    asio::async_write(socket_, asio::buffer(pending_.front()),
                      [self = shared_from_this()](boost::system::error_code ec, std::size_t) {
                        self->on_written(ec);
                      });
  }

  void on_written(boost::system::error_code ec) {
    if (closed_) return;
    if (ec) {
      close(ec.message());
      return;
    }
    pending_bytes_ -= pending_.front().size();
    pending_.pop_front();
    if (!pending_.empty()) {
      write();
    } else if (finishing_) {
      close("client quit");
    }
  }

  tcp::socket socket_;
  asio::steady_timer idle_;
  std::unique_ptr<proto::ProtocolSession> session_;
  std::string client_;
  std::string address_;
  ConnectionLog log_;
  std::size_t max_pending_;
  double idle_timeout_s_;
  std::shared_ptr<std::size_t> live_;
  std::array<char, 4096> buffer_{};
  std::deque<std::string> pending_;
  std::size_t pending_bytes_ = 0;
  bool finishing_ = false;
  bool closed_ = false;
};

TcpProtocolServer::TcpProtocolServer(asio::io_context& io, std::string name, SessionFactory factory,
                                     ConnectionLog log, TcpServerLimits limits)
    : acceptor_(io),
      name_(std::move(name)),
      factory_(std::move(factory)),
      log_(std::move(log)),
      limits_(limits),
      live_(std::make_shared<std::size_t>(0)) {}

TcpProtocolServer::~TcpProtocolServer() { close(); }

Result<std::unique_ptr<TcpProtocolServer>> TcpProtocolServer::open(
    asio::io_context& io, const std::string& name, const std::string& bind_address,
    unsigned short port, SessionFactory factory, ConnectionLog log, TcpServerLimits limits) {
  std::unique_ptr<TcpProtocolServer> server(
      new TcpProtocolServer(io, name, std::move(factory), std::move(log), limits));
  if (auto ok = listen_on(server->acceptor_, name, bind_address, port); !ok) return ok.error();
  server->accept_next();
  return server;
}

unsigned short TcpProtocolServer::port() const { return bound_port(acceptor_); }

std::size_t TcpProtocolServer::clients() const { return *live_; }

void TcpProtocolServer::close() {
  boost::system::error_code ignored;
  acceptor_.close(ignored);
  for (auto& weak : connections_) {
    if (auto c = weak.lock()) c->close("server stopping");
  }
  connections_.clear();
}

std::size_t TcpProtocolServer::clients_from(const std::string& address) {
  std::erase_if(connections_, [](const auto& w) { return w.expired(); });
  return static_cast<std::size_t>(
      std::count_if(connections_.begin(), connections_.end(), [&](auto& w) {
        const auto c = w.lock();
        return c && c->open() && c->address() == address;
      }));
}

void TcpProtocolServer::accept_next() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted || !acceptor_.is_open()) return;
    if (!ec) {
      boost::system::error_code peer_ec;
      const auto peer = socket.remote_endpoint(peer_ec);
      const std::string address = peer_ec ? std::string("?") : peer.address().to_string();
      const std::string client =
          name_ + " " + (peer_ec ? address : address + ":" + std::to_string(peer.port()));
      if (*live_ >= limits_.max_clients) {
        if (log_)
          log_(client, "refused: " + std::to_string(limits_.max_clients) + " clients connected");
        socket.close(peer_ec);
      } else if (clients_from(address) >= limits_.max_per_address) {
        if (log_) {
          log_(client, "refused: " + std::to_string(limits_.max_per_address) +
                           " clients connected from " + address);
        }
        socket.close(peer_ec);
      } else {
        start_connection(std::move(socket), client, address);
      }
    }
    accept_next();
  });
}

void TcpProtocolServer::start_connection(tcp::socket socket, const std::string& client,
                                         const std::string& address) {
  boost::system::error_code ignored;
  socket.set_option(tcp::no_delay(true), ignored);
  std::unique_ptr<proto::ProtocolSession> session;
  try {
    session = factory_(client);
  } catch (const std::exception& e) {
    if (log_) log_(client, std::string("refused: internal error: ") + e.what());
    socket.close(ignored);
    return;
  }
  auto connection = std::make_shared<Connection>(std::move(socket), std::move(session), client,
                                                 address, log_, limits_, live_);
  connections_.push_back(connection);
  if (log_) log_(client, "connected");
  connection->start();
}

}  // namespace azt::linux_os
