#pragma once
// The check byte of the EncoderHub's CRC-8 frames (azt/proto/hub_frame.hpp): COBS frames the
// bytes but does not protect them, so our hub appends this CRC to the seed's five bytes.
//
// Shared with the AVR hub firmware (avr-gcc 5.4): C++14, <stdint.h>/<stddef.h> only, no heap, no
// exceptions, no STL. `int` is 16 bits there, so every shift is done on unsigned or 32-bit types.

#include <stddef.h>
#include <stdint.h>

namespace azt {
namespace proto {

/// CRC-8/AUTOSAR (the AUTOSAR E2E "CRC8H2F"): polynomial 0x2F, initial value 0xFF, no
/// reflection, final XOR 0xFF; check value 0xDF for the ASCII bytes "123456789", residue 0x42
/// (Greg Cook, "Catalogue of parametrised CRC algorithms"). Why this one:
/// - it detects every error burst up to 8 bits, so any one corrupted data byte, and every error
///   of up to 3 bits in our 48-bit codeword (Hamming distance 4; 0x97 in the notation of Koopman
///   & Chakravarty, DSN 2004, whose tables compare 8-bit polynomials this way);
/// - a corrupted COBS code byte re-parses the chunk instead, and the payload error it makes is
///   built from code-chain hop lengths. Polynomial 0x07 (CRC-8/SMBUS, CRC-8/I-432-1) misses some
///   of those; 0x2F misses none, so no single corrupted byte on the wire gets through (both
///   checked exhaustively in tests/unit/proto/hub_crc8_test.cpp);
/// - the initial value and final XOR keep an all-zero payload from having CRC 0, so a zeroed
///   buffer, or seven 0x01 bytes on the line, is not a valid 0/0 reading.
/// Bitwise rather than table-driven: 40 iterations per frame, and no 256-byte table in AVR flash.
constexpr uint8_t hub_crc8(const uint8_t* data, size_t size) {
  uint8_t crc = 0xFF;
  for (size_t i = 0; i < size; ++i) {
    crc = static_cast<uint8_t>(crc ^ data[i]);
    for (int bit = 0; bit < 8; ++bit) {
      const bool top = (crc & 0x80U) != 0;
      crc = static_cast<uint8_t>(crc << 1U);
      if (top) crc = static_cast<uint8_t>(crc ^ 0x2FU);
    }
  }
  return static_cast<uint8_t>(crc ^ 0xFFU);
}

}  // namespace proto
}  // namespace azt
