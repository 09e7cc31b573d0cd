#pragma once
// A UDP server that answers datagrams (PstRotator's `<PST>` protocol, port 12000).
//
// PstRotator sends its position replies to the sender's host on port + 1 (12001) rather than to
// the source port (reference §8.6); `reply_port` selects that, and 0 answers the source port.
//
// A datagram longer than the buffer is never handed on cut short: the kernel reports its real
// length (recv(2), MSG_TRUNC on Internet datagram sockets), and such a datagram is dropped whole
// and reported to `on_oversized` (before, the cut last line of a 1,610-byte datagram had
// been read as a false receiver reading).

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "azt/linux/asio.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

class UdpDatagramServer {
 public:
  /// Returns the reply datagram, or an empty string for none. `client` names the sender.
  using Handler = std::function<std::string(std::string_view datagram, const std::string& client)>;
  /// Told of each dropped datagram: its real length in bytes and its sender.
  using OversizedHandler = std::function<void(std::size_t bytes, const std::string& client)>;
  /// The longest datagram accepted (an Ethernet MTU's payload).
  static constexpr std::size_t kMaxDatagramBytes = 1500;

  static Result<std::unique_ptr<UdpDatagramServer>> open(
      boost::asio::io_context& io, const std::string& name, const std::string& bind_address,
      unsigned short port, unsigned short reply_port, Handler handler);
  ~UdpDatagramServer();
  UdpDatagramServer(const UdpDatagramServer&) = delete;
  UdpDatagramServer& operator=(const UdpDatagramServer&) = delete;

  [[nodiscard]] unsigned short port() const;
  void on_oversized(OversizedHandler handler) { oversized_ = std::move(handler); }
  void close();

 private:
  UdpDatagramServer(boost::asio::io_context& io, std::string name, unsigned short reply_port,
                    Handler handler);
  void receive();
  void received(std::size_t real_bytes);
  [[nodiscard]] std::string client_name() const;

  boost::asio::ip::udp::socket socket_;
  std::string name_;
  unsigned short reply_port_;
  Handler handler_;
  OversizedHandler oversized_;
  std::array<char, kMaxDatagramBytes> buffer_{};
  boost::asio::ip::udp::endpoint sender_;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace azt::linux_os
