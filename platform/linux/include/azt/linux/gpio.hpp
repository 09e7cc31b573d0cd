#pragma once
// GPIO lines (relays, bridge enables, limit switches, the E-stop and PTT inputs) behind a seam,
// so the station's logic is tested against fakes and runs on the kernel's GPIO character device
// through libgpiod (libgpiod_lines.hpp). Levels are logical: `active_low` lines are inverted by
// the provider, so `true` always means asserted (relay energized, switch tripped, PTT pressed).

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

struct GpioLineSpec {
  std::string chip = "gpiochip0";  ///< a name (gpiochip0), a path (/dev/gpiochip0) or a label
  unsigned offset = 0;             ///< the line's number on that chip (BCM number on a Pi)
  bool active_low = false;
  std::string key;  ///< the configuration key, for errors ("[gpio] estop")
};

enum class GpioBias { AsIs, PullUp, PullDown };

class GpioOutput {
 public:
  GpioOutput() = default;
  GpioOutput(const GpioOutput&) = delete;
  GpioOutput& operator=(const GpioOutput&) = delete;
  /// Implementations release the line de-asserted where the hardware lets them.
  virtual ~GpioOutput() = default;
  virtual Result<bool> set(bool active) = 0;
  [[nodiscard]] virtual bool active() const = 0;
  [[nodiscard]] virtual const GpioLineSpec& spec() const = 0;
};

class GpioInput {
 public:
  GpioInput() = default;
  GpioInput(const GpioInput&) = delete;
  GpioInput& operator=(const GpioInput&) = delete;
  virtual ~GpioInput() = default;
  /// The level after the last edge seen (read once when the line was requested).
  [[nodiscard]] virtual bool active() const = 0;
  [[nodiscard]] virtual const GpioLineSpec& spec() const = 0;
};

/// Called from the event loop after an edge with the line's new logical level.
using GpioEdgeHandler = std::function<void(bool active)>;

/// One edge as the kernel queued it, for pulse counting: none merged with the next, each with
/// the kernel's timestamp (CLOCK_MONOTONIC, the clock std::chrono::steady_clock reads on Linux).
struct GpioEdgeEvent {
  bool active = true;  ///< the logical level the line went to
  std::chrono::steady_clock::time_point at;
};
using GpioEventHandler = std::function<void(const GpioEdgeEvent& event)>;

class GpioProvider {
 public:
  GpioProvider() = default;
  GpioProvider(const GpioProvider&) = delete;
  GpioProvider& operator=(const GpioProvider&) = delete;
  virtual ~GpioProvider() = default;

  /// Requests `spec` as an output driven to `initial` at once. Fails naming the key, the chip
  /// and line, and the reason (no such chip, line taken by another program).
  virtual Result<std::unique_ptr<GpioOutput>> output(const GpioLineSpec& spec, bool initial) = 0;
  /// Requests `spec` as an input with both edges reported to `on_edge` from the event loop.
  virtual Result<std::unique_ptr<GpioInput>> input(const GpioLineSpec& spec, GpioBias bias,
                                                   GpioEdgeHandler on_edge) = 0;
  /// Requests `spec` as an input reporting every edge separately with its timestamp (a pulse
  /// sensor: input()'s one report per burst would lose pulses). Providers that cannot refuse.
  virtual Result<std::unique_ptr<GpioInput>> event_input(const GpioLineSpec& spec, GpioBias bias,
                                                         GpioEventHandler on_event);
};

/// "[gpio] estop (gpiochip0 line 26)": how errors and logs name a line.
std::string describe(const GpioLineSpec& spec);

}  // namespace azt::linux_os
