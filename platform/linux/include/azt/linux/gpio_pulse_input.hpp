#pragma once
// A pulse-counted axis's lines on GPIO (docs/hardware.md, "Pulse sensors and homing"): a reed or
// Hall sensor's line or a quadrature pair, and the home switch, each edge queued from the event
// loop with the kernel's timestamp and handed to the control tick by take_edges(). Never blocks.

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "azt/linux/gpio.hpp"
#include "azt/ports/pulse_input.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

struct GpioPulseLines {
  /// One line (a single-channel sensor) or two (quadrature A, then B).
  std::vector<GpioLineSpec> pulse;
  GpioLineSpec home;  ///< the home switch: active when closed
  GpioBias bias = GpioBias::PullUp;
};

class GpioPulseInput final : public ports::PulseInput {
 public:
  /// Requests the lines from `gpio`. `epoch` is the control loop's time zero: an edge at steady
  /// time t is at (t − epoch) seconds on the loop's clock. Fails naming the line.
  static Result<std::unique_ptr<GpioPulseInput>> open(GpioProvider& gpio,
                                                      const GpioPulseLines& lines,
                                                      std::chrono::steady_clock::time_point epoch);

  /// The queued edges of every line, in timestamp order.
  std::vector<ports::PulseEdge> take_edges() override;
  [[nodiscard]] bool home_closed() const override;
  [[nodiscard]] std::string describe() const override;
  /// Edges dropped because the queue was full (the loop stalled for thousands of pulses): the
  /// count is then wrong, and the next pass of the home switch says by how much.
  [[nodiscard]] std::uint64_t overflowed() const { return overflowed_; }

  /// The most edges queued between two ticks.
  static constexpr std::size_t kMaxQueued = 4096;

 private:
  explicit GpioPulseInput(std::chrono::steady_clock::time_point epoch) : epoch_(epoch) {}
  void queue(ports::PulseLine line, const GpioEdgeEvent& event);

  std::chrono::steady_clock::time_point epoch_;
  std::vector<std::unique_ptr<GpioInput>> pulse_lines_;
  std::unique_ptr<GpioInput> home_;
  std::vector<ports::PulseEdge> edges_;
  std::uint64_t overflowed_ = 0;
  std::string description_;
};

}  // namespace azt::linux_os
