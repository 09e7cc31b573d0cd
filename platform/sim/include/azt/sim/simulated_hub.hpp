#pragma once
// The EncoderHub of a simulated station: what turns the plants' encoder counts into the frames
// the station's sensors read. Two kinds: the plain model (model_hub.hpp: a frame built from the
// counts at each read, with injected loss and corruption) and the real firmware on a simulated
// ATmega328P (azt/avr/firmware_hub.hpp, "firmware in the loop"). Both deliver frames through
// the daemon's own HubDecoder.

#include <optional>
#include <string>

#include "azt/proto/hub_decoder.hpp"
#include "azt/sim/sim_antenna.hpp"

namespace azt::sim {

/// A decoded frame and when its last byte arrived, on the control loop's clock.
struct HubArrival {
  proto::HubReading reading;
  double at_s = 0.0;
};

class SimulatedHub {
 public:
  SimulatedHub() = default;
  SimulatedHub(const SimulatedHub&) = delete;
  SimulatedHub& operator=(const SimulatedHub&) = delete;
  SimulatedHub(SimulatedHub&&) = delete;
  SimulatedHub& operator=(SimulatedHub&&) = delete;
  virtual ~SimulatedHub() = default;

  /// The longest plant step between two runs of the hub, in seconds.
  [[nodiscard]] virtual double step_s() const = 0;
  /// The plants have just moved on by `step_s` (at most step_s()): the hub runs as long.
  virtual void run(const SimAntenna& plants, double step_s) = 0;
  /// At `now_s`, once the plants and the hub have run up to it: the newest frame that arrived
  /// since the last call, if any.
  virtual std::optional<HubArrival> take_frame(const SimAntenna& plants, double now_s) = 0;
  /// The decoder's counters: frames taken, rejected.
  [[nodiscard]] virtual proto::HubCounters counters() const = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace azt::sim
