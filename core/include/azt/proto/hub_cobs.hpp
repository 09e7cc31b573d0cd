#pragma once
// Consistent Overhead Byte Stuffing (Cheshire & Baker, "Consistent Overhead Byte Stuffing",
// IEEE/ACM Trans. Networking 7(2), 1999) as the EncoderHub frames use it (azt/proto/hub_frame.hpp):
// standard COBS without the 0xFF code, for payloads shorter than 254 bytes. The seed's hub encodes
// backwards and in place, which yields the same bytes for such payloads.
//
// Shared with the AVR hub firmware (avr-gcc 5.4): C++14, <stdint.h>/<stddef.h> only, no heap, no
// exceptions, no STL. `int` is 16 bits there, so every shift is done on unsigned or 32-bit types.

#include <stddef.h>
#include <stdint.h>

namespace azt {
namespace proto {

/// COBS without the 0xFF code (runs of 254 non-zero bytes) handles payloads up to this size;
/// the seed limits its packets to "< 254 bytes" the same way.
constexpr size_t kHubCobsMaxPayloadBytes = 253;

/// COBS-encodes `size` payload bytes into `out` WITHOUT the trailing delimiter.
/// Returns the encoded length (size + 1), or 0 if size > kHubCobsMaxPayloadBytes or the output
/// does not fit. Standard COBS (Cheshire & Baker): each code byte n means n - 1 data bytes follow,
/// then an implied 0x00, except after the last block.
inline size_t hub_cobs_encode(const uint8_t* payload, size_t size, uint8_t* out, size_t capacity) {
  if (size > kHubCobsMaxPayloadBytes || capacity < size + 1) return 0;
  size_t code_at = 0;  // where the current block's code byte goes
  uint8_t code = 1;    // 1 + data bytes in the current block
  size_t o = 1;
  for (size_t i = 0; i < size; ++i) {
    if (payload[i] == 0) {
      out[code_at] = code;
      code_at = o++;
      code = 1;
    } else {
      out[o++] = payload[i];
      ++code;
    }
  }
  out[code_at] = code;
  return o;
}

/// Decodes one COBS chunk (no delimiter inside or at the end) into `out`.
/// Returns false if a code byte is 0x00 or points past the end, a data byte is 0x00, a 0xFF code
/// appears (never needed below 254 bytes), or the output does not fit. `decoded` gets the length.
inline bool hub_cobs_decode(const uint8_t* chunk, size_t size, uint8_t* out, size_t capacity,
                            size_t& decoded) {
  size_t i = 0;
  size_t o = 0;
  while (i < size) {
    const uint8_t code = chunk[i++];
    if (code == 0 || code == 0xFF || i + (code - 1U) > size) return false;
    for (uint8_t k = 1; k < code; ++k) {
      if (chunk[i] == 0 || o >= capacity) return false;
      out[o++] = chunk[i++];
    }
    if (i < size) {  // the last block has no implied zero after it
      if (o >= capacity) return false;
      out[o++] = 0;
    }
  }
  decoded = o;
  return true;
}

}  // namespace proto
}  // namespace azt
