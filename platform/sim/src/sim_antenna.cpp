#include "azt/sim/sim_antenna.hpp"

#include <array>

namespace azt::sim {
namespace {

proto::HubAccept accept_for(proto::HubFrameVersion v) {
  return v == proto::HubFrameVersion::Crc8 ? proto::HubAccept::Crc8Only
                                           : proto::HubAccept::SeedOnly;
}

}  // namespace

SimAntenna::SimAntenna(const AxisParams& az, const AxisParams& el,
                       proto::HubFrameVersion frame_version, LinkFaults link, std::uint64_t seed)
    : az_(az),
      el_(el),
      frame_version_(frame_version),
      link_(link),
      decoder_(accept_for(frame_version)),
      rng_(seed) {}

void SimAntenna::step(double az_duty, double el_duty, double dt_s, int substeps) {
  const double dt = dt_s / substeps;
  for (int i = 0; i < substeps; ++i) {
    az_.step(az_duty, dt);
    el_.step(el_duty, dt);
  }
}

std::optional<control::AzEl> SimAntenna::transmit_frame() {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (!link_started_) {
    // Our hub firmware sends a delimiter at boot, so the first frame is not taken for the tail
    // of an earlier one.
    proto::HubFrame unused{};
    decoder_.push(0x00, unused);
    link_started_ = true;
  }
  if (u(rng_) < link_.frame_loss) return std::nullopt;
  const proto::HubReading reading{az_.encoder_bits(), el_.encoder_bits(), az_.encoder_raw(),
                                  el_.encoder_raw()};
  std::array<std::uint8_t, proto::kHubMaxFrameBytes> frame{};
  const std::size_t n =
      proto::encode_hub_frame(reading, frame_version_, frame.data(), frame.size());
  std::optional<control::AzEl> out;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint8_t byte = frame[i];
    if (u(rng_) < link_.byte_corruption) byte = static_cast<std::uint8_t>(rng_() & 0xFF);
    proto::HubFrame decoded{};
    if (decoder_.push(byte, decoded) == proto::HubFrameStatus::Ok) {
      const proto::HubReading& r = decoded.reading;
      out = control::AzEl{proto::hub_raw_to_deg(r.az_raw, r.az_bits),
                          proto::hub_raw_to_deg(r.el_raw, r.el_bits)};
    }
  }
  return out;
}

}  // namespace azt::sim
