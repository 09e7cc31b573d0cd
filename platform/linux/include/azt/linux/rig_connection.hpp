#pragma once
// One rig's link as the daemon's loop holds it (docs/radio.md "In the daemon"), whatever carries
// it: Hamlib's rigctld over TCP (rigctld_link.hpp) or libhamlib itself on a worker thread
// (hamlib_rig.hpp). Both queue through the core's RigPort, report what the rig answered and
// their link's changes through RigLinkEvents on the loop, reconnect by themselves with a
// back-off, and report a loss once and the return once, never every retry.

#include <functional>
#include <string>

#include "azt/radio/rig_port.hpp"

namespace azt::linux_os {

enum class RigLinkState { Connecting, Up, Down };

struct RigLinkEvents {
  /// The link came up (`why` empty) or went down (`why` says why): once per change.
  std::function<void(RigLinkState state, const std::string& why)> link;
  /// Every answer the rig gave (reads, writes, refusals).
  std::function<void(const radio::RigEvent&)> event;
};

class RigConnection {
 public:
  RigConnection() = default;
  RigConnection(const RigConnection&) = delete;
  RigConnection& operator=(const RigConnection&) = delete;
  RigConnection(RigConnection&&) = delete;
  RigConnection& operator=(RigConnection&&) = delete;
  virtual ~RigConnection() = default;

  /// Where frequencies and reads are queued; call flush() after queueing.
  virtual radio::RigPort& port() = 0;
  /// Sends what is queued (as soon as the rig is free).
  virtual void flush() = 0;
  [[nodiscard]] virtual RigLinkState state() const = 0;
  /// Why the link is down ("" while up or before the first failure).
  [[nodiscard]] virtual const std::string& down_reason() const = 0;
  /// The rig and where it is, for log lines: "rigctld at 127.0.0.1:4532".
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace azt::linux_os
