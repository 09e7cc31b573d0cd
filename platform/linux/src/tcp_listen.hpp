#pragma once
// Opening a listening TCP socket the way every server of the daemon does (rotctld, the console),
// and the port a server's socket is bound to:
// a literal IP address only (no name lookups that could block), SO_REUSEADDR so a restart can
// bind at once, and errors that name the server and the address.

#include <string>

#include "azt/linux/asio.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

/// Binds `acceptor` to `bind_address`:`port` and listens; the error names `name`.
inline Result<bool> listen_on(boost::asio::ip::tcp::acceptor& acceptor, const std::string& name,
                              const std::string& bind_address, unsigned short port) {
  using tcp = boost::asio::ip::tcp;
  boost::system::error_code ec;
  const auto address = boost::asio::ip::make_address(bind_address, ec);
  if (ec) return fail(name + ": bind address '" + bind_address + "' is not an IP address");
  const tcp::endpoint endpoint(address, port);
  const auto where = name + " on " + bind_address + ":" + std::to_string(port);
  if (acceptor.open(endpoint.protocol(), ec); ec) return fail(where + ": " + ec.message());
  acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
  if (acceptor.bind(endpoint, ec); ec) return fail(where + ": " + ec.message());
  if (acceptor.listen(boost::asio::socket_base::max_listen_connections, ec); ec) {
    return fail(where + ": " + ec.message());
  }
  return true;
}

/// The port a bound socket or acceptor listens on (0 when it is not bound): the servers' port(),
/// for a server opened on port 0 to let the kernel choose.
template <typename Socket>
unsigned short bound_port(const Socket& socket) {
  boost::system::error_code ec;
  const auto endpoint = socket.local_endpoint(ec);
  return ec ? 0 : endpoint.port();
}

}  // namespace azt::linux_os
