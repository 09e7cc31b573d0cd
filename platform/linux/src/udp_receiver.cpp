#include "azt/linux/udp_receiver.hpp"

#include <sys/socket.h>

namespace azt::linux_os {

namespace asio = boost::asio;
using asio::ip::udp;

UdpReceiver::UdpReceiver(asio::io_context& io, std::size_t max_bytes, Handler handler,
                         OversizedHandler oversized)
    : socket_(io),
      buffer_(max_bytes),
      handler_(std::move(handler)),
      oversized_(std::move(oversized)) {}

UdpReceiver::~UdpReceiver() { close(); }

Result<std::unique_ptr<UdpReceiver>> UdpReceiver::open(asio::io_context& io,
                                                       const std::string& address,
                                                       unsigned short port, std::size_t max_bytes,
                                                       Handler handler,
                                                       OversizedHandler oversized) {
  std::unique_ptr<UdpReceiver> r(
      new UdpReceiver(io, max_bytes, std::move(handler), std::move(oversized)));
  boost::system::error_code ec;
  const auto ip = asio::ip::make_address(address, ec);
  if (ec) return fail("'" + address + "' is not an IP address");
  const auto where = address + ":" + std::to_string(port) + "/udp";
  r->multicast_ = ip.is_multicast();
  // A group is received on the port of any address; a unicast address is bound as it is.
  const udp::endpoint bind_to(r->multicast_
                                  ? (ip.is_v6() ? asio::ip::address(asio::ip::address_v6::any())
                                                : asio::ip::address(asio::ip::address_v4::any()))
                                  : ip,
                              port);
  if (r->socket_.open(bind_to.protocol(), ec); ec) return fail(where + ": " + ec.message());
  if (r->multicast_) {
    if (r->socket_.set_option(udp::socket::reuse_address(true), ec); ec) {
      return fail(where + ": " + ec.message());
    }
  }
  if (r->socket_.bind(bind_to, ec); ec) return fail(where + ": " + ec.message());
  if (r->multicast_) {
    if (r->socket_.set_option(asio::ip::multicast::join_group(ip), ec); ec) {
      return fail(where + ": cannot join the group: " + ec.message());
    }
  }
  r->receive();
  return r;
}

unsigned short UdpReceiver::port() const {
  boost::system::error_code ec;
  const auto endpoint = socket_.local_endpoint(ec);
  return ec ? 0 : endpoint.port();
}

void UdpReceiver::close() {
  *alive_ = false;
  boost::system::error_code ignored;
  socket_.close(ignored);
}

void UdpReceiver::receive() {
  // MSG_TRUNC: n is the datagram's real length even when it did not fit (Linux, recv(2)).
  socket_.async_receive_from(asio::buffer(buffer_), sender_, MSG_TRUNC,
                             [this, alive = alive_](boost::system::error_code ec, std::size_t n) {
                               if (!*alive) return;
                               if (!ec) {
                                 const std::string sender = sender_.address().to_string() + ":" +
                                                            std::to_string(sender_.port());
                                 if (n > buffer_.size()) {
                                   if (oversized_) oversized_(n, sender);
                                 } else {
                                   try {
                                     handler_(std::string_view(buffer_.data(), n), sender);
                                   } catch (const std::exception&) {
                                     // A fault handling one datagram drops that datagram, never the
                                     // daemon.
                                   }
                                 }
                               }
                               receive();
                             });
}

}  // namespace azt::linux_os
