#include "azt/linux/gpio_pulse_input.hpp"

#include <algorithm>
#include <utility>

namespace azt::linux_os {

Result<std::unique_ptr<GpioPulseInput>> GpioPulseInput::open(
    GpioProvider& gpio, const GpioPulseLines& lines, std::chrono::steady_clock::time_point epoch) {
  if (lines.pulse.empty() || lines.pulse.size() > 2) {
    return fail("a pulse sensor has one line (single) or two (quadrature A and B)");
  }
  std::unique_ptr<GpioPulseInput> input(new GpioPulseInput(epoch));
  GpioPulseInput* self = input.get();
  for (std::size_t i = 0; i < lines.pulse.size(); ++i) {
    const ports::PulseLine line = lines.pulse.size() == 1 ? ports::PulseLine::Pulse
                                  : i == 0                ? ports::PulseLine::QuadratureA
                                                          : ports::PulseLine::QuadratureB;
    auto in = gpio.event_input(lines.pulse[i], lines.bias,
                               [self, line](const GpioEdgeEvent& e) { self->queue(line, e); });
    if (!in) return in.error();
    input->pulse_lines_.push_back(std::move(in).value());
  }
  auto home = gpio.event_input(lines.home, lines.bias, [self](const GpioEdgeEvent& e) {
    self->queue(ports::PulseLine::Home, e);
  });
  if (!home) return home.error();
  input->home_ = std::move(home).value();
  input->description_ = (lines.pulse.size() == 1 ? "pulses on " : "quadrature on ") +
                        linux_os::describe(lines.pulse.front()) + ", home switch " +
                        linux_os::describe(lines.home);
  return input;
}

void GpioPulseInput::queue(ports::PulseLine line, const GpioEdgeEvent& event) {
  if (edges_.size() >= kMaxQueued) {
    ++overflowed_;
    return;
  }
  const std::chrono::duration<double> since = event.at - epoch_;
  edges_.push_back({line, event.active, since.count()});
}

std::vector<ports::PulseEdge> GpioPulseInput::take_edges() {
  // Each line's edges come in order; lines read in one loop turn interleave by their stamps
  // (the count at a home switch edge must be the count at its time).
  std::stable_sort(
      edges_.begin(), edges_.end(),
      [](const ports::PulseEdge& a, const ports::PulseEdge& b) { return a.at_s < b.at_s; });
  return std::exchange(edges_, {});
}

bool GpioPulseInput::home_closed() const { return home_->active(); }

std::string GpioPulseInput::describe() const { return description_; }

}  // namespace azt::linux_os
