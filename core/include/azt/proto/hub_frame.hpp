#pragma once
// EncoderHub frames: the RS485 link from the encoder hub to the controller.
//
// Wire format (seed 000, "Encoder Hub Data Format"): each frame is a COBS-encoded payload followed
// by one 0x00 delimiter (Cheshire & Baker, "Consistent Overhead Byte Stuffing", IEEE/ACM Trans.
// Networking 7(2), 1999). The seed's hub encodes backwards and in place, which yields the same
// bytes as standard COBS for payloads shorter than 254 bytes; its FRAME_START is the COBS code
// byte, not an extra delimiter. Decoded payloads:
//
//   seed version (5 bytes):  EncBITS, EL_hi, EL_lo, AZ_hi, AZ_lo
//   CRC-8 version (6 bytes): the same five bytes, then CRC-8/AUTOSAR over them
//
// What the five bytes mean (the EncBITS nibbles, the counts, the angles) is azt/proto/
// hub_reading.hpp; the COBS and the CRC-8 are hub_cobs.hpp and hub_crc8.hpp; the streaming decoder
// with a counter per outcome is hub_decoder.hpp. This header is the frame: its versions, sizes,
// encoder and the checks that decide what a chunk between two delimiters was.
//
// The CRC version is ours: COBS frames the bytes but does not protect them (nanocobs #43 and the
// reliability notes: "COBS gives framing, not integrity"). The two versions differ only in length,
// so a receiver that knows its hub sends CRC frames must accept only those (HubAccept::Crc8Only):
// otherwise a corrupted CRC frame can shrink into a valid-looking seed frame.
//
// Shared with the AVR hub firmware (avr-gcc 5.4): C++14, <stdint.h>/<stddef.h> only, no heap, no
// exceptions, no STL. `int` is 16 bits there, so every shift is done on unsigned or 32-bit types.

#include <stddef.h>
#include <stdint.h>

#include "azt/proto/hub_cobs.hpp"
#include "azt/proto/hub_crc8.hpp"
#include "azt/proto/hub_reading.hpp"

namespace azt {
namespace proto {

/// Seed: the 5-byte payload of seed 000. Crc8: the same plus a CRC-8 byte (our hub firmware).
enum class HubFrameVersion : uint8_t { Seed, Crc8 };

/// A decoded frame: the reading and the version it came in.
struct HubFrame {
  HubReading reading;
  HubFrameVersion version;
};

/// Which versions a decoder takes. Configure the one your hub sends; Any is for diagnostics and
/// for links whose hub is unknown (it gives up the CRC's protection, see the header comment).
enum class HubAccept : uint8_t { Any, SeedOnly, Crc8Only };

/// What a chunk of bytes between two delimiters turned out to be.
enum class HubFrameStatus : uint8_t {
  Pending,       ///< no delimiter on this byte: nothing finished (HubDecoder::push only)
  Ok,            ///< a valid frame
  Empty,         ///< nothing between two delimiters: allowed (senders may lead with 0x00)
  Unsynced,      ///< bytes before the first delimiter after start-up: the tail of a frame
  Overlong,      ///< longer than any frame: lost delimiter, wrong baud rate, noise
  WrongLength,   ///< encoded length fits no version: truncated frame or a split by a stray 0x00
  BadCobs,       ///< a COBS code byte points past the end of the chunk
  WrongVersion,  ///< a well-formed frame of a version this decoder was told not to accept
  BadCrc,        ///< CRC-8 version whose check byte does not match
  BadNibble,     ///< a resolution nibble of 1..8
  OutOfRange,    ///< a raw value >= 2^bits
};

/// Payload sizes, decoded.
constexpr size_t kHubSeedPayloadBytes = 5;
constexpr size_t kHubCrc8PayloadBytes = 6;
/// COBS adds one code byte to a payload shorter than 254 bytes (Cheshire & Baker).
constexpr size_t kHubSeedEncodedBytes = kHubSeedPayloadBytes + 1;
constexpr size_t kHubCrc8EncodedBytes = kHubCrc8PayloadBytes + 1;
/// Whole frames, delimiter included: the seed's DATA[7], and ours.
constexpr size_t kHubSeedFrameBytes = kHubSeedEncodedBytes + 1;
constexpr size_t kHubCrc8FrameBytes = kHubCrc8EncodedBytes + 1;
/// The largest frame on the wire, delimiter included: size encode buffers with this.
constexpr size_t kHubMaxFrameBytes = kHubCrc8FrameBytes;

/// Writes one whole frame (COBS bytes and the 0x00 delimiter) for `r` into `out`.
/// Returns the bytes written (kHubSeedFrameBytes or kHubCrc8FrameBytes), or 0 if the reading is
/// invalid (bits outside 9..16, raw >= 2^bits) or `capacity` is too small.
inline size_t encode_hub_frame(const HubReading& r, HubFrameVersion version, uint8_t* out,
                               size_t capacity) {
  if (out == nullptr || !hub_reading_valid(r)) return 0;
  // An axis error is said only in CRC-8 frames: nibble 1, the code as the raw value.
  if (version == HubFrameVersion::Seed && hub_reading_has_error(r)) return 0;
  const bool az_bad = r.az_error != HubAxisError::None;
  const bool el_bad = r.el_error != HubAxisError::None;
  const uint8_t az_nibble = az_bad ? kHubErrorNibble : hub_bits_to_nibble(r.az_bits);
  const uint8_t el_nibble = el_bad ? kHubErrorNibble : hub_bits_to_nibble(r.el_bits);
  const uint16_t az_raw = az_bad ? static_cast<uint8_t>(r.az_error) : r.az_raw;
  const uint16_t el_raw = el_bad ? static_cast<uint8_t>(r.el_error) : r.el_raw;
  uint8_t payload[kHubCrc8PayloadBytes] = {static_cast<uint8_t>(az_nibble << 4U | el_nibble),
                                           static_cast<uint8_t>(el_raw >> 8U),
                                           static_cast<uint8_t>(el_raw & 0xFFU),
                                           static_cast<uint8_t>(az_raw >> 8U),
                                           static_cast<uint8_t>(az_raw & 0xFFU),
                                           0};
  size_t payload_bytes = kHubSeedPayloadBytes;
  if (version == HubFrameVersion::Crc8) {
    payload[kHubSeedPayloadBytes] = hub_crc8(payload, kHubSeedPayloadBytes);
    payload_bytes = kHubCrc8PayloadBytes;
  }
  if (capacity < payload_bytes + 2) return 0;
  const size_t encoded = hub_cobs_encode(payload, payload_bytes, out, capacity - 1);
  if (encoded == 0) return 0;
  out[encoded] = 0;
  return encoded + 1;
}

namespace detail {

constexpr bool hub_accepts(HubAccept accept, HubFrameVersion version) {
  return accept == HubAccept::Any ||
         (accept == HubAccept::SeedOnly && version == HubFrameVersion::Seed) ||
         (accept == HubAccept::Crc8Only && version == HubFrameVersion::Crc8);
}

constexpr uint16_t hub_be16(uint8_t hi, uint8_t lo) {
  return static_cast<uint16_t>(static_cast<uint16_t>(hi) << 8U | lo);
}

/// The checks after COBS, in the order that names the likeliest cause: integrity first (a
/// corrupted frame is reported as corrupted), then meaning.
inline HubFrameStatus hub_check_payload(const uint8_t* payload, HubFrameVersion version,
                                        HubReading& reading) {
  if (version == HubFrameVersion::Crc8 &&
      hub_crc8(payload, kHubSeedPayloadBytes) != payload[kHubSeedPayloadBytes]) {
    return HubFrameStatus::BadCrc;
  }
  const uint8_t az_nibble = static_cast<uint8_t>(payload[0] >> 4U);
  const uint8_t el_nibble = static_cast<uint8_t>(payload[0] & 0x0FU);
  HubReading r{hub_nibble_to_bits(az_nibble), hub_nibble_to_bits(el_nibble),
               hub_be16(payload[3], payload[4]), hub_be16(payload[1], payload[2])};
  // Ours: in a CRC-8 frame, nibble 1 says the axis has an error, coded in its raw field.
  const bool errors_allowed = version == HubFrameVersion::Crc8;
  if (errors_allowed && az_nibble == kHubErrorNibble) {
    r.az_error = static_cast<HubAxisError>(r.az_raw > kHubAxisErrorLast ? 0xFFU : r.az_raw);
    r.az_raw = 0;
  }
  if (errors_allowed && el_nibble == kHubErrorNibble) {
    r.el_error = static_cast<HubAxisError>(r.el_raw > kHubAxisErrorLast ? 0xFFU : r.el_raw);
    r.el_raw = 0;
  }
  if ((r.az_bits == 0 && r.az_error == HubAxisError::None) ||
      (r.el_bits == 0 && r.el_error == HubAxisError::None)) {
    return HubFrameStatus::BadNibble;
  }
  if (!hub_reading_valid(r)) return HubFrameStatus::OutOfRange;
  reading = r;
  return HubFrameStatus::Ok;
}

}  // namespace detail

/// Decodes one chunk: the bytes between two delimiters, without them. `out` is written only when
/// the result is HubFrameStatus::Ok. Never returns Pending or Unsynced.
inline HubFrameStatus decode_hub_chunk(const uint8_t* chunk, size_t size, HubAccept accept,
                                       HubFrame& out) {
  if (size == 0) return HubFrameStatus::Empty;
  if (size > kHubCrc8EncodedBytes) return HubFrameStatus::Overlong;
  // Valid COBS below 254 bytes decodes to exactly one byte less, so the length alone says which
  // version this can be; checking it first reports truncated frames as such.
  if (size != kHubSeedEncodedBytes && size != kHubCrc8EncodedBytes) {
    return HubFrameStatus::WrongLength;
  }
  uint8_t payload[kHubCrc8PayloadBytes] = {};
  size_t decoded = 0;
  if (!hub_cobs_decode(chunk, size, payload, sizeof payload, decoded) || decoded != size - 1) {
    return HubFrameStatus::BadCobs;
  }
  const HubFrameVersion version =
      decoded == kHubCrc8PayloadBytes ? HubFrameVersion::Crc8 : HubFrameVersion::Seed;
  if (!detail::hub_accepts(accept, version)) return HubFrameStatus::WrongVersion;
  HubReading reading{};
  const HubFrameStatus status = detail::hub_check_payload(payload, version, reading);
  if (status == HubFrameStatus::Ok) out = HubFrame{reading, version};
  return status;
}

/// Short names for logs and JSON ("ok", "bad_crc", ...), matching the HubCounters fields.
inline const char* hub_status_name(HubFrameStatus status) {
  switch (status) {
    case HubFrameStatus::Pending:
      return "pending";
    case HubFrameStatus::Ok:
      return "ok";
    case HubFrameStatus::Empty:
      return "empty";
    case HubFrameStatus::Unsynced:
      return "unsynced";
    case HubFrameStatus::Overlong:
      return "overlong";
    case HubFrameStatus::WrongLength:
      return "wrong_length";
    case HubFrameStatus::BadCobs:
      return "bad_cobs";
    case HubFrameStatus::WrongVersion:
      return "wrong_version";
    case HubFrameStatus::BadCrc:
      return "bad_crc";
    case HubFrameStatus::BadNibble:
      return "bad_nibble";
    case HubFrameStatus::OutOfRange:
      return "out_of_range";
  }
  return "unknown";
}

}  // namespace proto
}  // namespace azt
