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
// EncBITS = AZ nibble << 4 | EL nibble; a nibble holds the resolution in bits, 9..15 as is and 16
// as 0 (16 does not fit in a nibble; 2..8 are invalid, and 1 is an axis error in CRC-8 frames,
// see HubAxisError). Raw values are big-endian, right-aligned,
// and must be < 2^bits. Angle = raw * 360 / 2^bits degrees: the seed's "65535" for 16 bits is a
// slip (it would put raw 65535 at 360°, the same direction as raw 0).
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

/// Resolution limits of the hub (seed 000: "limited to values between 9 and 16 bits").
constexpr uint8_t kHubMinBits = 9;
constexpr uint8_t kHubMaxBits = 16;

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
/// COBS without the 0xFF code (runs of 254 non-zero bytes) handles payloads up to this size;
/// the seed limits its packets to "< 254 bytes" the same way.
constexpr size_t kHubCobsMaxPayloadBytes = 253;

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

/// CRC-8/AUTOSAR (the AUTOSAR E2E "CRC8H2F"): polynomial 0x2F, initial value 0xFF, no
/// reflection, final XOR 0xFF; check value 0xDF for the ASCII bytes "123456789", residue 0x42
/// (Greg Cook, "Catalogue of parametrised CRC algorithms"). Why this one:
/// - it detects every error burst up to 8 bits, so any one corrupted data byte, and every error
///   of up to 3 bits in our 48-bit codeword (Hamming distance 4; 0x97 in the notation of Koopman
///   & Chakravarty, DSN 2004, whose tables compare 8-bit polynomials this way);
/// - a corrupted COBS code byte re-parses the chunk instead, and the payload error it makes is
///   built from code-chain hop lengths. Polynomial 0x07 (CRC-8/SMBUS, CRC-8/I-432-1) misses some
///   of those; 0x2F misses none, so no single corrupted byte on the wire gets through (both
///   checked exhaustively in tests/unit/hub_frame_test.cpp);
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

/// One counter per outcome. Every 0x00 pushed into a HubDecoder adds exactly one to exactly one
/// counter, so their sum (chunks()) equals the delimiters seen since construction or reset().
/// Counters wrap modulo 2^32: take rates from differences in unsigned arithmetic.
struct HubCounters {
  uint32_t frames_seed;
  uint32_t frames_crc8;
  uint32_t empty;
  uint32_t unsynced;
  uint32_t overlong;
  uint32_t wrong_length;
  uint32_t bad_cobs;
  uint32_t wrong_version;
  uint32_t bad_crc;
  uint32_t bad_nibble;
  uint32_t out_of_range;

  uint32_t frames_ok() const { return frames_seed + frames_crc8; }
  /// Frames lost to the link or the sender: what an error budget ("> 20 bad frames a minute is
  /// a fault", OnStepX) should count. Empty chunks and the one unsynced start-up chunk are not
  /// link errors.
  uint32_t rejected() const {
    return overlong + wrong_length + bad_cobs + wrong_version + bad_crc + bad_nibble + out_of_range;
  }
  uint32_t chunks() const { return frames_ok() + rejected() + empty + unsynced; }
};

/// Where a new or reset decoder starts.
/// AwaitDelimiter: discard everything up to the first 0x00, as the seed's controller does
/// ("searches for the frame_end delimiter character"): on a live serial port the first bytes are
/// usually the tail of a frame. InSync: the input starts at a frame boundary (a capture file, a
/// test, a pipe).
enum class HubSync : uint8_t { AwaitDelimiter, InSync };

/// Streaming decoder: push bytes as they arrive; a fixed 7-byte buffer, no heap.
/// After a chunk overflows the buffer, bytes are discarded up to the next 0x00, which ends the
/// chunk as Overlong; every delimiter resets the framing, so one stray byte costs at most the frame
/// it lands in (electricui-embedded #180).
class HubDecoder {
 public:
  explicit HubDecoder(HubAccept accept, HubSync sync = HubSync::AwaitDelimiter)
      : accept_(accept), sync_(sync) {
    reset();
  }

  /// Feeds one byte. Returns Pending unless `byte` is a delimiter; then returns what the chunk it
  /// ends was, and on Ok writes the frame to `out` (untouched otherwise).
  HubFrameStatus push(uint8_t byte, HubFrame& out) {
    if (byte != 0) {
      if (state_ == State::AwaitingDelimiter) {
        had_bytes_ = true;
      } else if (state_ == State::Collecting) {
        if (length_ < kHubCrc8EncodedBytes) {
          buffer_[length_++] = byte;
        } else {
          state_ = State::Discarding;
        }
      }
      return HubFrameStatus::Pending;
    }
    const HubFrameStatus status = finish_chunk(out);
    uint32_t* counter = counter_for(counters_, status, out);
    if (counter != nullptr) ++*counter;
    state_ = State::Collecting;
    length_ = 0;
    had_bytes_ = false;
    return status;
  }

  const HubCounters& counters() const { return counters_; }

  /// Drops any partial frame and waits for the next delimiter, keeping the counters (a link that
  /// was lost and is back: what came before the break must not be glued to what comes after).
  void resync() {
    state_ = State::AwaitingDelimiter;
    length_ = 0;
    had_bytes_ = false;
  }

  /// Back to the freshly constructed state: framing as chosen by HubSync, counters zero.
  void reset() {
    counters_ = HubCounters{};
    state_ = sync_ == HubSync::InSync ? State::Collecting : State::AwaitingDelimiter;
    length_ = 0;
    had_bytes_ = false;
  }

 private:
  enum class State : uint8_t { AwaitingDelimiter, Collecting, Discarding };

  HubFrameStatus finish_chunk(HubFrame& out) const {
    switch (state_) {
      case State::AwaitingDelimiter:
        return had_bytes_ ? HubFrameStatus::Unsynced : HubFrameStatus::Empty;
      case State::Discarding:
        return HubFrameStatus::Overlong;
      case State::Collecting:
        break;
    }
    return decode_hub_chunk(buffer_, length_, accept_, out);
  }

  /// The counter an outcome adds one to; none for Pending. `frame` is read only on Ok.
  static uint32_t* counter_for(HubCounters& c, HubFrameStatus status, const HubFrame& frame) {
    switch (status) {
      case HubFrameStatus::Pending:
        return nullptr;
      case HubFrameStatus::Ok:
        return frame.version == HubFrameVersion::Crc8 ? &c.frames_crc8 : &c.frames_seed;
      case HubFrameStatus::Empty:
        return &c.empty;
      case HubFrameStatus::Unsynced:
        return &c.unsynced;
      case HubFrameStatus::Overlong:
        return &c.overlong;
      case HubFrameStatus::WrongLength:
        return &c.wrong_length;
      case HubFrameStatus::BadCobs:
        return &c.bad_cobs;
      case HubFrameStatus::WrongVersion:
        return &c.wrong_version;
      case HubFrameStatus::BadCrc:
        return &c.bad_crc;
      case HubFrameStatus::BadNibble:
        return &c.bad_nibble;
      case HubFrameStatus::OutOfRange:
        return &c.out_of_range;
    }
    return nullptr;
  }

  HubAccept accept_;
  HubSync sync_;
  State state_ = State::AwaitingDelimiter;
  uint8_t buffer_[kHubCrc8EncodedBytes] = {};
  size_t length_ = 0;
  bool had_bytes_ = false;  // any byte since the last delimiter while awaiting the first one
  HubCounters counters_ = {};
};

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
