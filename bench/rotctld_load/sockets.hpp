#pragma once
// rotctld_load's sockets: the server's address, non-blocking connects, the descriptor limit.

#include <sys/socket.h>

#include <optional>

#include "options.hpp"

namespace rotctld_load {

struct Endpoint {
  sockaddr_storage addr{};
  socklen_t len = 0;
};

/// The server's address from --host and --port, or nullopt after saying why on stderr.
std::optional<Endpoint> resolve(const Options& o);

// Starts a non-blocking connect with TCP_NODELAY (requests are a few bytes: Nagle plus delayed
// ACK would otherwise add tens of ms). Returns the fd, or -1 when the connect failed at once.
int start_connect(const Endpoint& ep);

bool connect_succeeded(int fd);

// Raises the soft descriptor limit toward the hard one when C + K sockets need it.
void ensure_fd_limit(int sockets);

}  // namespace rotctld_load
