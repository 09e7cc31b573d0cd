#include "azt/sim/model_hub.hpp"

#include <array>

namespace azt::sim {
namespace {

proto::HubAccept accept_for(proto::HubFrameVersion v) {
  return v == proto::HubFrameVersion::Crc8 ? proto::HubAccept::Crc8Only
                                           : proto::HubAccept::SeedOnly;
}

}  // namespace

ModelHub::ModelHub(std::uint8_t az_bits, std::uint8_t el_bits, proto::HubFrameVersion frame_version,
                   LinkFaults link, std::uint64_t seed)
    : frame_version_(frame_version),
      link_(link),
      decoder_(accept_for(frame_version)),
      rng_(seed),
      az_bits_(az_bits),
      el_bits_(el_bits) {}

std::optional<HubArrival> ModelHub::take_frame(const SimAntenna& plants, double now_s) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (!link_started_) {
    // Our hub firmware sends a delimiter at boot, so the first frame is not taken for the tail
    // of an earlier one.
    proto::HubFrame unused{};
    decoder_.push(0x00, unused);
    link_started_ = true;
  }
  if (u(rng_) < link_.frame_loss) return std::nullopt;
  const proto::HubReading reading{plants.az().encoder_bits(), plants.el().encoder_bits(),
                                  plants.az().encoder_raw(), plants.el().encoder_raw()};
  std::array<std::uint8_t, proto::kHubMaxFrameBytes> frame{};
  const std::size_t n =
      proto::encode_hub_frame(reading, frame_version_, frame.data(), frame.size());
  std::optional<HubArrival> out;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint8_t byte = frame.at(i);
    if (u(rng_) < link_.byte_corruption) byte = static_cast<std::uint8_t>(rng_() & 0xFF);
    proto::HubFrame decoded{};
    if (decoder_.push(byte, decoded) == proto::HubFrameStatus::Ok) {
      out = HubArrival{decoded.reading, now_s};
    }
  }
  return out;
}

std::string ModelHub::describe() const {
  return "simulated antenna (" + std::to_string(az_bits_) + "/" + std::to_string(el_bits_) +
         "-bit encoders)";
}

}  // namespace azt::sim
