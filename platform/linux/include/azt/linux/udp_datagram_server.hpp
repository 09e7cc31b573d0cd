#pragma once
// A UDP server that answers datagrams (PstRotator's `<PST>` protocol, port 12000).
//
// PstRotator sends its position replies to the sender's host on port + 1 (12001) rather than to
// the source port (reference §8.6); `reply_port` selects that, and 0 answers the source port.

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

  static Result<std::unique_ptr<UdpDatagramServer>> open(
      boost::asio::io_context& io, const std::string& name, const std::string& bind_address,
      unsigned short port, unsigned short reply_port, Handler handler);
  ~UdpDatagramServer();
  UdpDatagramServer(const UdpDatagramServer&) = delete;
  UdpDatagramServer& operator=(const UdpDatagramServer&) = delete;

  [[nodiscard]] unsigned short port() const;
  void close();

 private:
  UdpDatagramServer(boost::asio::io_context& io, std::string name, unsigned short reply_port,
                    Handler handler);
  void receive();

  boost::asio::ip::udp::socket socket_;
  std::string name_;
  unsigned short reply_port_;
  Handler handler_;
  std::array<char, 1500> buffer_{};
  boost::asio::ip::udp::endpoint sender_;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace azt::linux_os
