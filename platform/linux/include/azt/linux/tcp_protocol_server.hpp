#pragma once
// A TCP server hosting one ProtocolSession per connection (rotctld), on the daemon's io_context.
//
// Bounded in every direction (reference R12): at most `max_clients` connections and at most
// `max_per_address` from one address (more are accepted and closed at once, so one host cannot
// take every slot from Gpredict), a connection silent for `idle_timeout_s` is closed, at most
// `max_pending_output` bytes queued for a client that does not read (it is disconnected), reads
// of at most 4 KiB at a time into the session's own bounded assembler. No handler blocks; an
// error, or an exception from a session, closes that one connection and never the server.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "azt/linux/asio.hpp"
#include "azt/proto/rotator_service.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

struct TcpServerLimits {
  std::size_t max_clients = 256;
  std::size_t max_per_address = 16;
  /// Gpredict polls every 1 s or so and Hamlib's clients hold no idle connections, so 10 min of
  /// silence means a client that is gone (a dropped Wi-Fi leaves no FIN). 0: never.
  double idle_timeout_s = 600.0;
  std::size_t max_pending_output = 64 * 1024;
};

/// Makes the session for a new client; `client` names it ("rotctld 127.0.0.1:50312").
using SessionFactory =
    std::function<std::unique_ptr<proto::ProtocolSession>(const std::string& client)>;
/// Connection events for the log: "connected", "disconnected: …", "refused: …".
using ConnectionLog = std::function<void(const std::string& client, const std::string& event)>;

class TcpProtocolServer {
 public:
  /// Binds and listens; an error names the address and the reason (address in use, …).
  static Result<std::unique_ptr<TcpProtocolServer>> open(
      boost::asio::io_context& io, const std::string& name, const std::string& bind_address,
      unsigned short port, SessionFactory factory, ConnectionLog log, TcpServerLimits limits = {});
  ~TcpProtocolServer();
  TcpProtocolServer(const TcpProtocolServer&) = delete;
  TcpProtocolServer& operator=(const TcpProtocolServer&) = delete;

  /// The port actually bound (useful with port 0).
  [[nodiscard]] unsigned short port() const;
  [[nodiscard]] std::size_t clients() const;
  /// Stops accepting and closes every connection.
  void close();

  class Connection;

 private:
  TcpProtocolServer(boost::asio::io_context& io, std::string name, SessionFactory factory,
                    ConnectionLog log, TcpServerLimits limits);
  void accept_next();
  [[nodiscard]] std::size_t clients_from(const std::string& address);
  void start_connection(boost::asio::ip::tcp::socket socket, const std::string& client,
                        const std::string& address);

  boost::asio::ip::tcp::acceptor acceptor_;
  std::string name_;
  SessionFactory factory_;
  ConnectionLog log_;
  TcpServerLimits limits_;
  std::shared_ptr<std::size_t> live_;  ///< connections alive; shared with them
  std::vector<std::weak_ptr<Connection>> connections_;
};

}  // namespace azt::linux_os
