#include "azt/linux/udp_datagram_server.hpp"

#include <sys/socket.h>

#include "tcp_listen.hpp"

namespace azt::linux_os {

namespace asio = boost::asio;
using asio::ip::udp;

UdpDatagramServer::UdpDatagramServer(asio::io_context& io, std::string name,
                                     unsigned short reply_port, Handler handler)
    : socket_(io), name_(std::move(name)), reply_port_(reply_port), handler_(std::move(handler)) {}

UdpDatagramServer::~UdpDatagramServer() { close(); }

Result<std::unique_ptr<UdpDatagramServer>> UdpDatagramServer::open(
    asio::io_context& io, const std::string& name, const std::string& bind_address,
    unsigned short port, unsigned short reply_port, Handler handler) {
  std::unique_ptr<UdpDatagramServer> server(
      new UdpDatagramServer(io, name, reply_port, std::move(handler)));
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(bind_address, ec);
  if (ec) return fail(name + ": bind address '" + bind_address + "' is not an IP address");
  const udp::endpoint endpoint(address, port);
  const auto where = name + " on " + bind_address + ":" + std::to_string(port) + "/udp";
  if (server->socket_.open(endpoint.protocol(), ec); ec) return fail(where + ": " + ec.message());
  if (server->socket_.bind(endpoint, ec); ec) return fail(where + ": " + ec.message());
  server->receive();
  return server;
}

unsigned short UdpDatagramServer::port() const { return bound_port(socket_); }

void UdpDatagramServer::close() {
  *alive_ = false;
  boost::system::error_code ignored;
  socket_.close(ignored);
}

void UdpDatagramServer::receive() {
  // MSG_TRUNC: n is the datagram's real length even when it did not fit (Linux, recv(2)).
  socket_.async_receive_from(asio::buffer(buffer_), sender_, MSG_TRUNC,
                             [this, alive = alive_](boost::system::error_code ec, std::size_t n) {
                               if (!*alive) return;
                               if (!ec) received(n);
                               receive();
                             });
}

std::string UdpDatagramServer::client_name() const {
  return name_ + " " + sender_.address().to_string() + ":" + std::to_string(sender_.port());
}

void UdpDatagramServer::received(std::size_t real_bytes) {
  if (real_bytes > buffer_.size()) {
    if (oversized_) oversized_(real_bytes, client_name());
    return;
  }
  std::string reply;
  try {
    reply = handler_(std::string_view(buffer_.data(), real_bytes), client_name());
  } catch (const std::exception&) {
    // A fault handling one datagram drops that datagram, never the daemon.
    reply.clear();
  }
  if (reply.empty()) return;
  udp::endpoint to = sender_;
  if (reply_port_ != 0) to.port(reply_port_);
  boost::system::error_code send_ec;
  // Datagrams are small and the socket is non-blocking-safe for them; a dropped reply is what
  // UDP means anyway.
  socket_.send_to(asio::buffer(reply), to, 0, send_ec);
}

}  // namespace azt::linux_os
