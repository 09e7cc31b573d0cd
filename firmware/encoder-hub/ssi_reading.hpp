#pragma once
// One SSI word from an absolute encoder, checked and turned into a count (docs/encoder-hub.md).
// Pure: the hub firmware and the host tests compile the same code (C++14, no heap, no STL; `int` is
// 16 bits on the AVR, so every shift is on an unsigned or 32-bit type).
//
// A word is read MSB first. Before the first clock the data line must be idle high (an encoder
// that is ready; a line stuck low or an encoder without power fails), and for generic SSI one
// clock after the last data bit the line must be low (the SSI monoflop time; a line pulled up
// with no encoder answering stays high). Both are sampled by the reader and passed in here; the
// AS5045 is not clocked past its 18 bits (its chip-select ends the word), so an undriven line
// shows there as a word of all ones instead.
//
// AS5045-class (MAB25, ETS25, HH12): 18 bits, D11..D0 then OCF, COF, LIN, MagINC, MagDEC and an
// even parity bit over the 17 before it (ams AS5045 datasheet, "SSI data content"). The angle is
// used only with OCF high, COF and LIN low, and not MagINC and MagDEC both high (out of range;
// the datasheet allows it only in its optional yellow mode, which we do not use). LIN "may still
// be used" per the datasheet; a hub that points a kilowatt dish does not.
//
// Generic SSI: 9..16 data bits, binary or Gray code, no status and no parity: only the line
// checks above and the double read protect it (a bit that is wrong the same way twice passes).

#include <stdint.h>

#include "azt/proto/hub_frame.hpp"

namespace azt {
namespace hub {

enum class EncoderCode : uint8_t { Binary, Gray };

/// The 18 bits of an AS5045-class word.
constexpr uint8_t kAs5045WordBits = 18;
constexpr uint8_t kAs5045DataBits = 12;
constexpr uint32_t kAs5045AllOnes = (uint32_t{1} << kAs5045WordBits) - 1U;

/// One axis's reading: its count, or why there is none.
struct SsiCount {
  uint16_t raw;
  proto::HubAxisError error;
};

/// Gray code to binary (each bit is the XOR of the Gray bits at and above it).
constexpr uint16_t gray_to_binary(uint16_t gray) {
  uint16_t binary = gray;
  for (uint16_t shift = 1; shift < 16; shift = static_cast<uint16_t>(shift << 1U)) {
    binary = static_cast<uint16_t>(binary ^ (binary >> shift));
  }
  return binary;
}

/// Binary to Gray code (for encoder models and tests).
constexpr uint16_t binary_to_gray(uint16_t binary) {
  return static_cast<uint16_t>(binary ^ (binary >> 1U));
}

/// Number of 1 bits in the low `bits` bits of `word`.
constexpr uint8_t ones(uint32_t word, uint8_t bits) {
  uint8_t n = 0;
  for (uint8_t i = 0; i < bits; ++i) n = static_cast<uint8_t>(n + ((word >> i) & 1UL));
  return n;
}

/// The line checks every SSI read makes (see the header comment).
constexpr bool ssi_line_ok(bool idle_high, bool trailer_low) { return idle_high && trailer_low; }

/// An AS5045-class word (18 bits, right-aligned) read after the line checks.
constexpr SsiCount decode_as5045(uint32_t word, bool idle_high, bool trailer_low) {
  using proto::HubAxisError;
  // All ones is the pull-up of a line no encoder drives (its parity is even, and COF would
  // otherwise be blamed).
  if (!ssi_line_ok(idle_high, trailer_low) || word == kAs5045AllOnes) {
    return SsiCount{0, HubAxisError::NoEncoder};
  }
  if (ones(word, kAs5045WordBits) % 2U != 0) return SsiCount{0, HubAxisError::Parity};
  const bool ocf = (word >> 5U) & 1UL;
  const bool cof = (word >> 4U) & 1UL;
  const bool lin = (word >> 3U) & 1UL;
  const bool mag_inc = (word >> 2U) & 1UL;
  const bool mag_dec = (word >> 1U) & 1UL;
  if (!ocf) return SsiCount{0, HubAxisError::NotReady};
  if (cof) return SsiCount{0, HubAxisError::CordicOverflow};
  if (lin) return SsiCount{0, HubAxisError::Linearity};
  if (mag_inc && mag_dec) return SsiCount{0, HubAxisError::MagnetRange};
  return SsiCount{static_cast<uint16_t>(word >> 6U), HubAxisError::None};
}

/// The AS5045 word for a count with its status bits and parity (for encoder models and tests).
constexpr uint32_t make_as5045_word(uint16_t raw, bool ocf, bool cof, bool lin, bool mag_inc,
                                    bool mag_dec) {
  const uint32_t w = (static_cast<uint32_t>(raw & 0x0FFFU) << 6U) | (uint32_t{ocf} << 5U) |
                     (uint32_t{cof} << 4U) | (uint32_t{lin} << 3U) | (uint32_t{mag_inc} << 2U) |
                     (uint32_t{mag_dec} << 1U);
  return w | (ones(w, kAs5045WordBits) % 2U);  // even parity over all 18 bits
}

/// A generic SSI word of `bits` data bits (right-aligned) read after the line checks.
constexpr SsiCount decode_generic_ssi(uint32_t word, uint8_t bits, EncoderCode code, bool idle_high,
                                      bool trailer_low) {
  using proto::HubAxisError;
  if (!ssi_line_ok(idle_high, trailer_low)) return SsiCount{0, HubAxisError::NoEncoder};
  const uint16_t data = static_cast<uint16_t>(word & (proto::hub_raw_limit(bits) - 1UL));
  return SsiCount{code == EncoderCode::Gray ? gray_to_binary(data) : data, HubAxisError::None};
}

}  // namespace hub
}  // namespace azt
