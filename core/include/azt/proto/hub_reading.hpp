#pragma once
// What an EncoderHub frame carries: one reading of both encoders (seed 000, "Encoder Hub Data
// Format" and "Encoder Resolution calculations"), the resolution nibbles of its EncBITS byte, and
// the angles its counts stand for. The frames that carry it are azt/proto/hub_frame.hpp.
//
// EncBITS = AZ nibble << 4 | EL nibble; a nibble holds the resolution in bits, 9..15 as is and 16
// as 0 (16 does not fit in a nibble; 2..8 are invalid, and 1 is an axis error in CRC-8 frames,
// see HubAxisError). Raw values are big-endian, right-aligned,
// and must be < 2^bits. Angle = raw * 360 / 2^bits degrees: the seed's "65535" for 16 bits is a
// slip (it would put raw 65535 at 360°, the same direction as raw 0).
//
// Shared with the AVR hub firmware (avr-gcc 5.4): C++14, <stdint.h>/<stddef.h> only, no heap, no
// exceptions, no STL. `int` is 16 bits there, so every shift is done on unsigned or 32-bit types.

#include <stddef.h>
#include <stdint.h>

namespace azt {
namespace proto {

/// Why the hub has no position for an axis at this instant (docs/encoder-hub.md). Only the CRC-8
/// frame version (ours) carries it: the axis's nibble is kHubErrorNibble (1, which the seed's
/// format never uses) and its raw field holds this code. The seed version cannot say it; a hub
/// sending seed frames skips the frame instead.
enum class HubAxisError : uint8_t {
  None = 0,
  NoEncoder = 1,       ///< the data line was not idle-high, or did not drop after the word
  Parity = 2,          ///< the encoder's even parity failed (AS5045-class)
  NotReady = 3,        ///< OCF low: the encoder's offset compensation has not finished
  CordicOverflow = 4,  ///< COF high: the angle is invalid (magnet out of its tolerances)
  Linearity = 5,       ///< LIN high: the angle may be wrong (magnet out of its tolerances)
  MagnetRange = 6,     ///< MagINC and MagDEC both high: the field is out of range
  Disagree = 7,        ///< two readings of one instant differ by more than allowed
  BadJumpers = 8,      ///< the axis's jumpers select no encoder type the firmware knows
};
constexpr uint8_t kHubAxisErrorLast = 8;
constexpr uint8_t kHubErrorNibble = 1;

/// One reading of both encoders as the hub reports it. An axis with an error has bits 0 and
/// raw 0: there is no position for it in this frame.
struct HubReading {
  uint8_t az_bits;  ///< azimuth encoder resolution, 9..16 bits
  uint8_t el_bits;  ///< elevation encoder resolution, 9..16 bits
  uint16_t az_raw;  ///< azimuth count, < 2^az_bits
  uint16_t el_raw;  ///< elevation count, < 2^el_bits
  HubAxisError az_error = HubAxisError::None;
  HubAxisError el_error = HubAxisError::None;
};

inline bool operator==(const HubReading& a, const HubReading& b) {
  return a.az_bits == b.az_bits && a.el_bits == b.el_bits && a.az_raw == b.az_raw &&
         a.el_raw == b.el_raw && a.az_error == b.az_error && a.el_error == b.el_error;
}
inline bool operator!=(const HubReading& a, const HubReading& b) { return !(a == b); }

/// Resolution limits of the hub (seed 000: "limited to values between 9 and 16 bits").
constexpr uint8_t kHubMinBits = 9;
constexpr uint8_t kHubMaxBits = 16;

constexpr bool hub_bits_valid(uint8_t bits) { return bits >= kHubMinBits && bits <= kHubMaxBits; }

/// 2^bits: one more than the largest raw value (0 for bits above 16). 32-bit so that 2^16 fits
/// on AVR, where int is 16 bits.
constexpr uint32_t hub_raw_limit(uint8_t bits) {
  return bits <= kHubMaxBits ? uint32_t{1} << bits : uint32_t{0};
}

/// One axis of a reading: a position (bits 9..16, raw < 2^bits), or an error with nothing else.
constexpr bool hub_axis_valid(uint8_t bits, uint16_t raw, HubAxisError error) {
  return error == HubAxisError::None
             ? hub_bits_valid(bits) && raw < hub_raw_limit(bits)
             : bits == 0 && raw == 0 && static_cast<uint8_t>(error) <= kHubAxisErrorLast;
}

constexpr bool hub_reading_valid(const HubReading& r) {
  return hub_axis_valid(r.az_bits, r.az_raw, r.az_error) &&
         hub_axis_valid(r.el_bits, r.el_raw, r.el_error);
}

constexpr bool hub_reading_has_error(const HubReading& r) {
  return r.az_error != HubAxisError::None || r.el_error != HubAxisError::None;
}

/// The error in words, for logs and faults ("parity").
inline const char* hub_axis_error_name(HubAxisError error) {
  switch (error) {
    case HubAxisError::None:
      return "none";
    case HubAxisError::NoEncoder:
      return "no encoder answers";
    case HubAxisError::Parity:
      return "parity error";
    case HubAxisError::NotReady:
      return "encoder not ready (OCF low)";
    case HubAxisError::CordicOverflow:
      return "CORDIC overflow (COF): magnet out of tolerance";
    case HubAxisError::Linearity:
      return "linearity alarm (LIN): magnet out of tolerance";
    case HubAxisError::MagnetRange:
      return "magnetic field out of range (MagINC and MagDEC)";
    case HubAxisError::Disagree:
      return "two readings disagree";
    case HubAxisError::BadJumpers:
      return "the jumpers select no known encoder";
  }
  return "unknown error";
}

/// Resolution in bits -> nibble (16 -> 0). Precondition: hub_bits_valid(bits).
constexpr uint8_t hub_bits_to_nibble(uint8_t bits) {
  return bits == kHubMaxBits ? uint8_t{0} : bits;
}

/// Nibble -> resolution in bits (0 -> 16); 0 for the invalid nibbles 1..8 and values above 15.
constexpr uint8_t hub_nibble_to_bits(uint8_t nibble) {
  return nibble == 0 ? kHubMaxBits
                     : (nibble >= kHubMinBits && nibble < kHubMaxBits ? nibble : uint8_t{0});
}

/// The EncBITS byte: azimuth nibble high, elevation nibble low (seed 000).
constexpr uint8_t hub_enc_bits(uint8_t az_bits, uint8_t el_bits) {
  return static_cast<uint8_t>(hub_bits_to_nibble(az_bits) << 4U | hub_bits_to_nibble(el_bits));
}

/// Size of one encoder step in degrees (the seed's "1-bitDegree"): 360 / 2^bits.
/// Returns -1 for bits outside 9..16.
inline double hub_resolution_deg(uint8_t bits) {
  return hub_bits_valid(bits) ? 360.0 / static_cast<double>(hub_raw_limit(bits)) : -1.0;
}

/// Raw count -> degrees in [0, 360): raw * 360 / 2^bits (seed 000, "Encoder Resolution
/// calculations"). Returns -1 (no angle) if bits is outside 9..16 or raw >= 2^bits; readings that
/// a decoder accepted never give -1.
inline double hub_raw_to_deg(uint16_t raw, uint8_t bits) {
  if (!hub_bits_valid(bits) || raw >= hub_raw_limit(bits)) return -1.0;
  return static_cast<double>(raw) * hub_resolution_deg(bits);
}

}  // namespace proto
}  // namespace azt
