#pragma once
// The frame's reading from both axes' checked counts (docs/encoder-hub.md): an axis with an error,
// or whose jumpers select no known encoder, carries its error instead of a position.

#include "azt/proto/hub_frame.hpp"
#include "jumpers.hpp"
#include "ssi_reading.hpp"

namespace azt {
namespace hub {

constexpr SsiCount with_jumpers(const AxisJumpers& j, SsiCount c) {
  return j.kind == EncoderKind::Unknown ? SsiCount{0, proto::HubAxisError::BadJumpers} : c;
}

constexpr proto::HubReading hub_reading(const HubJumpers& j, SsiCount az, SsiCount el) {
  const SsiCount a = with_jumpers(j.az, az);
  const SsiCount e = with_jumpers(j.el, el);
  const bool a_ok = a.error == proto::HubAxisError::None;
  const bool e_ok = e.error == proto::HubAxisError::None;
  return proto::HubReading{a_ok ? j.az.bits : uint8_t{0},
                           e_ok ? j.el.bits : uint8_t{0},
                           a_ok ? a.raw : uint16_t{0},
                           e_ok ? e.raw : uint16_t{0},
                           a.error,
                           e.error};
}

}  // namespace hub
}  // namespace azt
