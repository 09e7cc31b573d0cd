#pragma once
// Opening serial devices the one way every adapter needs: raw 8N1, no flow control, no echo, no
// CR/LF translation, non-blocking for Asio, and exclusive (TIOCEXCL) so no other program reads
// the same port and steals bytes.

#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

/// Raw 8N1 at `baud` (one of 600 … 115200; 0 leaves the speed) on an open terminal.
Result<bool> make_raw_serial(int fd, unsigned baud);

/// Opens `device` raw and exclusive; the descriptor, or an error naming the device and why.
Result<int> open_serial_device(const std::string& device, unsigned baud);

}  // namespace azt::linux_os
