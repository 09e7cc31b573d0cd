#pragma once
// A UDP socket that only listens: datagrams from one address and port, unicast or a multicast
// group (WSJT-X and JTAlert share WSJT-X's messages through a group, docs/radio.md). For a group
// the socket binds the port on every address with SO_REUSEADDR, so several programs on the host
// can each receive the group, and joins it (ip(7), IP_ADD_MEMBERSHIP). Nothing is ever sent.
//
// A datagram longer than the buffer is never handed on cut short: the kernel reports its real
// length (recv(2), MSG_TRUNC), and it is passed to `oversized` whole-length only.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "azt/linux/asio.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

class UdpReceiver {
 public:
  using Handler = std::function<void(std::string_view datagram, const std::string& sender)>;
  using OversizedHandler = std::function<void(std::size_t bytes, const std::string& sender)>;

  /// `address`: an IPv4/IPv6 address to bind, or a multicast group to join. `max_bytes`: the
  /// longest datagram handed to `handler`.
  static Result<std::unique_ptr<UdpReceiver>> open(boost::asio::io_context& io,
                                                   const std::string& address, unsigned short port,
                                                   std::size_t max_bytes, Handler handler,
                                                   OversizedHandler oversized);
  ~UdpReceiver();
  UdpReceiver(const UdpReceiver&) = delete;
  UdpReceiver& operator=(const UdpReceiver&) = delete;

  [[nodiscard]] unsigned short port() const;
  [[nodiscard]] bool multicast() const { return multicast_; }
  void close();

 private:
  UdpReceiver(boost::asio::io_context& io, std::size_t max_bytes, Handler handler,
              OversizedHandler oversized);
  void receive();

  boost::asio::ip::udp::socket socket_;
  std::vector<char> buffer_;
  Handler handler_;
  OversizedHandler oversized_;
  boost::asio::ip::udp::endpoint sender_;
  bool multicast_ = false;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace azt::linux_os
