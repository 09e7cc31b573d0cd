#pragma once
// What the hub's jumpers select, read once at boot (docs/encoder-hub.md; seed 000: "bit resolution
// set by jumpers"). Pure: the firmware passes in which jumpers are fitted, as bits, and the host
// tests call the same function. A fitted jumper pulls its pin to ground; with none fitted the hub
// reads two AS5045-class encoders at 38400 baud, the common MAB25/HH12 station.
//
// Per axis, five jumpers (docs/encoder-hub.md has the pins of a Nano):
//   TYPE1 TYPE0   encoder
//     -     -     AS5045-class, 12 bits with status and parity (RES ignored)
//     -     x     generic SSI, binary
//     x     -     generic SSI, Gray code
//     x     x     none known: the axis reports BadJumpers in every frame
//   RES2 RES1 RES0  generic SSI resolution = 9 + (the three as a binary number): 9..16 bits
// Two more for the link: BAUD1 BAUD0 = -,- 38400; -,x 9600; x,- 115200; x,x 38400.

#include <stdint.h>

#include "ssi_reading.hpp"

namespace azt {
namespace hub {

enum class EncoderKind : uint8_t { As5045, GenericSsi, Unknown };

struct AxisJumpers {
  EncoderKind kind;
  uint8_t bits;  ///< 12 for AS5045-class; 9..16 for generic SSI; 0 when Unknown
  EncoderCode code;
};

struct HubJumpers {
  AxisJumpers az;
  AxisJumpers el;
  uint32_t baud;
};

/// Bit positions in the `fitted` word the firmware assembles from its pins (1 = fitted).
constexpr uint8_t kJumperRes0 = 0;  ///< RES0..RES2: bits 0..2 of an axis's five
constexpr uint8_t kJumperType0 = 3;
constexpr uint8_t kJumperType1 = 4;
constexpr uint8_t kJumpersPerAxis = 5;
constexpr uint8_t kJumperAzShift = 0;
constexpr uint8_t kJumperElShift = kJumpersPerAxis;
constexpr uint8_t kJumperBaud0 = 2 * kJumpersPerAxis;
constexpr uint8_t kJumperBaud1 = kJumperBaud0 + 1;

constexpr bool fitted_bit(uint16_t fitted, uint8_t bit) { return ((fitted >> bit) & 1U) != 0; }

/// One axis's five jumpers, the lowest at bit 0.
constexpr AxisJumpers axis_jumpers(uint8_t five) {
  const bool type0 = fitted_bit(five, kJumperType0);
  const bool type1 = fitted_bit(five, kJumperType1);
  if (!type0 && !type1)
    return AxisJumpers{EncoderKind::As5045, kAs5045DataBits, EncoderCode::Binary};
  if (type0 && type1) return AxisJumpers{EncoderKind::Unknown, 0, EncoderCode::Binary};
  const uint8_t bits = static_cast<uint8_t>(proto::kHubMinBits + (five & 0x07U));
  return AxisJumpers{EncoderKind::GenericSsi, bits,
                     type1 ? EncoderCode::Gray : EncoderCode::Binary};
}

constexpr uint32_t jumper_baud(bool baud0, bool baud1) {
  return baud0 && !baud1 ? 9600UL : (baud1 && !baud0 ? 115200UL : 38400UL);
}

constexpr HubJumpers read_jumpers(uint16_t fitted) {
  return HubJumpers{
      axis_jumpers(static_cast<uint8_t>((fitted >> kJumperAzShift) & 0x1FU)),
      axis_jumpers(static_cast<uint8_t>((fitted >> kJumperElShift) & 0x1FU)),
      jumper_baud(fitted_bit(fitted, kJumperBaud0), fitted_bit(fitted, kJumperBaud1))};
}

/// The bits an axis clocks in per read: the data bits, and for AS5045 its six status bits.
constexpr uint8_t word_bits(const AxisJumpers& a) {
  return a.kind == EncoderKind::As5045 ? kAs5045WordBits : a.bits;
}

}  // namespace hub
}  // namespace azt
