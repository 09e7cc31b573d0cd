#pragma once
// Idle connections: opened before the run, held silent throughout, checked at the end.

#include <cstdint>
#include <vector>

#include "sockets.hpp"

namespace rotctld_load {

// Opens the idle connections one at a time, paced (see kMaxHandshakesInFlight: an idle client
// never gets a reply, so pacing is the only gentle way to keep a small accept queue from
// overflowing).
std::vector<int> open_idle(const Endpoint& ep, int count);

// Closes the idle sockets; returns how many the server had closed (EOF or error) meanwhile.
std::uint64_t close_idle(const std::vector<int>& fds);

}  // namespace rotctld_load
