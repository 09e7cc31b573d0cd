#pragma once
// A look at something slow outside the daemon (chronyc, NetworkManager over D-Bus, sysfs) every
// few seconds, never on the event loop: `look` runs through the offload (a worker thread) and
// `seen` gets what it found back on the loop. One look at a time: asking while one is under way
// is answered by that one, so a hung tool never piles up jobs behind it.

#include <chrono>
#include <functional>
#include <memory>
#include <utility>

#include "azt/linux/asio.hpp"
#include "common/off_loop.hpp"

namespace azt::app {

template <typename Reading>
class PeriodicLook {
 public:
  PeriodicLook(boost::asio::io_context& io, double period_s, Offload offload,
               std::function<Reading()> look, std::function<void(Reading)> seen)
      : timer_(io),
        period_s_(period_s),
        offload_(std::move(offload)),
        look_(std::move(look)),
        seen_(std::move(seen)) {}

  /// Looks at once, then every period_s.
  void start() {
    now();
    arm();
  }

  /// A look now (none if one is under way).
  void now() {
    if (looking_) return;
    looking_ = true;
    auto reading = std::make_shared<Reading>();
    offload_([reading, look = look_] { *reading = look(); },
             [this, reading] {
               looking_ = false;
               seen_(std::move(*reading));
             });
  }

 private:
  void arm() {
    timer_.expires_after(std::chrono::duration_cast<boost::asio::steady_timer::duration>(
        std::chrono::duration<double>(period_s_)));
    timer_.async_wait([this](const boost::system::error_code& ec) {
      if (ec) return;
      now();
      arm();
    });
  }

  boost::asio::steady_timer timer_;
  double period_s_;
  Offload offload_;
  std::function<Reading()> look_;
  std::function<void(Reading)> seen_;
  bool looking_ = false;
};

}  // namespace azt::app
