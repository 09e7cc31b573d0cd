#pragma once
// The plain EncoderHub model: at each read it encodes the plants' counts as the firmware would
// (CRC-8 or the seed's frame version), passes the bytes through a link that may lose a frame or
// corrupt a byte, and decodes them with the daemon's HubDecoder.

#include <cstdint>
#include <random>

#include "azt/sim/simulated_hub.hpp"

namespace azt::sim {

/// Frame-level faults of the simulated EncoderHub link (probabilities per frame / per byte).
struct LinkFaults {
  double frame_loss = 0.0;       ///< a whole frame never arrives
  double byte_corruption = 0.0;  ///< each byte replaced by a random one
};

class ModelHub final : public SimulatedHub {
 public:
  /// The encoders' bits are the plants' (they only name the hub in describe()).
  ModelHub(std::uint8_t az_bits, std::uint8_t el_bits, proto::HubFrameVersion frame_version,
           LinkFaults link, std::uint64_t seed);

  /// The plants are integrated in steps of 10 ms; the model itself has no time of its own.
  [[nodiscard]] double step_s() const override { return 0.01; }
  void run(const SimAntenna& /*plants*/, double /*step_s*/) override {}
  std::optional<HubArrival> take_frame(const SimAntenna& plants, double now_s) override;
  [[nodiscard]] proto::HubCounters counters() const override { return decoder_.counters(); }
  [[nodiscard]] std::string describe() const override;

 private:
  proto::HubFrameVersion frame_version_;
  LinkFaults link_;
  proto::HubDecoder decoder_;
  std::mt19937_64 rng_;
  bool link_started_ = false;
  std::uint8_t az_bits_;
  std::uint8_t el_bits_;
};

}  // namespace azt::sim
