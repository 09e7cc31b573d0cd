#pragma once
// The simulated antenna: two plants (motor, gear, backlash, encoder) read through a simulated
// EncoderHub link whose frames go through the real decoder, with injected loss and corruption.
// Virtual-time simulations and the daemon's `sim` backend both drive it.

#include <cstdint>
#include <optional>
#include <random>

#include "azt/control/modes.hpp"
#include "azt/proto/hub_frame.hpp"
#include "azt/sim/axis_plant.hpp"

namespace azt::sim {

/// Frame-level faults of the simulated EncoderHub link (probabilities per frame / per byte).
struct LinkFaults {
  double frame_loss = 0.0;       ///< a whole frame never arrives
  double byte_corruption = 0.0;  ///< each byte replaced by a random one
};

class SimAntenna {
 public:
  SimAntenna(const AxisParams& az, const AxisParams& el, proto::HubFrameVersion frame_version,
             LinkFaults link, std::uint64_t seed);

  /// Advances both plants by `dt_s` with the given duties, in `substeps` integration steps.
  void step(double az_duty, double el_duty, double dt_s, int substeps);
  /// Sends one hub frame; the encoder angles (0..360 each) if it arrived intact.
  std::optional<control::AzEl> transmit_frame();
  void inject(bool azimuth, const AxisFault& fault) { (azimuth ? az_ : el_).inject(fault); }

  [[nodiscard]] const AxisPlant& az() const { return az_; }
  [[nodiscard]] const AxisPlant& el() const { return el_; }
  [[nodiscard]] const proto::HubDecoder& decoder() const { return decoder_; }

 private:
  AxisPlant az_;
  AxisPlant el_;
  proto::HubFrameVersion frame_version_;
  LinkFaults link_;
  proto::HubDecoder decoder_;
  std::mt19937_64 rng_;
  bool link_started_ = false;
};

}  // namespace azt::sim
