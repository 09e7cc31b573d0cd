#pragma once
// The edges of one pulse-counted axis's lines (docs/hardware.md, "Pulse sensors and homing"): a
// reed or Hall sensor's single line or a quadrature pair, and the home switch. Implemented by the
// Linux GPIO adapter (libgpiod's edge events, stamped by the kernel) and by tests driving a
// simulated plant.

#include <cstdint>
#include <string>
#include <vector>

namespace azt::ports {

/// Which line an edge came from.
enum class PulseLine : std::uint8_t {
  Pulse,        ///< a single-channel sensor's line (each rising edge is one pulse)
  QuadratureA,  ///< a quadrature sensor's channel A
  QuadratureB,  ///< … and B
  Home,         ///< the home switch (high: closed)
};

/// One edge: its line, its new level (high: active, the switch closed) and when it happened on
/// the control loop's monotonic clock.
struct PulseEdge {
  PulseLine line = PulseLine::Pulse;
  bool high = true;
  double at_s = 0.0;
};

class PulseInput {
 public:
  PulseInput() = default;
  PulseInput(const PulseInput&) = delete;
  PulseInput& operator=(const PulseInput&) = delete;
  PulseInput(PulseInput&&) = delete;
  PulseInput& operator=(PulseInput&&) = delete;
  virtual ~PulseInput() = default;

  /// The edges that arrived since the last call, oldest first; never waits for one. Called once
  /// a control tick.
  virtual std::vector<PulseEdge> take_edges() = 0;
  /// The home switch's level now (read once at start-up and when homing starts).
  [[nodiscard]] virtual bool home_closed() const = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace azt::ports
