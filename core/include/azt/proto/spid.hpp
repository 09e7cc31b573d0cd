#pragma once
// SPID Rot2Prog (and the Rot1Prog reply), server side: azeltrack emulates the controller for
// Hamlib rotctl -m 901/902 and other SPID clients.
//
// Wire format (reference/rotator-controllers-and-protocols.md §8.4, after Hamlib spid.txt/spid.c):
//   command, 13 bytes:  'W' H1 H2 H3 H4 PH V1 V2 V3 V4 PV K 0x20
//     K = 0x0F stop, 0x1F status, 0x2F set. For a set, H1..H4 / V1..V4 are ASCII digits of
//     H = PH * (360 + az) and V = PV * (360 + el), truncated by Hamlib; PH/PV are ignored by the
//     controller (it uses its own pulses per degree, which the client learnt from a status reply).
//     Rot1Prog sets carry H = 360 + az in H1..H3 with H4 = '0'. Hamlib fills stop and status
//     frames with zero bytes, so their digit fields are not checked.
//   Rot2Prog reply, 12 bytes: 'W' H1 H2 H3 H4 PH V1 V2 V3 V4 PV 0x20 with *binary* digits 0..9:
//     az = H1*100 + H2*10 + H3 + H4/10 - 360; el likewise. Example:
//     57 03 07 02 05 02 03 09 04 00 02 20 -> az 12.5, el 34.0, PH = PV = 2.
//   Rot1Prog reply, 5 bytes: 'W' H1 H2 H3 0x20, az = H1*100 + H2*10 + H3 - 360.
// A set gets no reply; stop and status reply with the position.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "azt/util/result.hpp"

namespace azt::proto {

inline constexpr std::size_t kSpidCommandBytes = 13;
inline constexpr std::size_t kSpidRot2ReplyBytes = 12;
inline constexpr std::size_t kSpidRot1ReplyBytes = 5;
inline constexpr std::uint8_t kSpidStart = 0x57;  // 'W'
inline constexpr std::uint8_t kSpidEnd = 0x20;
inline constexpr std::uint8_t kSpidKStop = 0x0F;
inline constexpr std::uint8_t kSpidKStatus = 0x1F;
inline constexpr std::uint8_t kSpidKSet = 0x2F;

using SpidFrame = std::array<std::uint8_t, kSpidCommandBytes>;

enum class SpidDialect { Rot2Prog, Rot1Prog };

enum class SpidOp { Stop, Status, Set };

struct SpidCommand {
  SpidOp op = SpidOp::Status;
  double az_deg = 0.0;  ///< Set only
  double el_deg = 0.0;  ///< Set only (always 0 for Rot1Prog)
  bool operator==(const SpidCommand&) const = default;
};

/// The emulated controller: resolution and the range a set target must lie in (Hamlib's
/// Rot2Prog model advertises az -180..540, el -20..210).
struct SpidConfig {
  SpidDialect dialect = SpidDialect::Rot2Prog;
  int pulses_per_deg_az = 2;  ///< PH: 1, 2 or 4
  int pulses_per_deg_el = 2;  ///< PV: 1, 2 or 4
  double az_min_deg = -180.0;
  double az_max_deg = 540.0;
  double el_min_deg = -20.0;
  double el_max_deg = 210.0;
};

/// Parses one 13-byte command frame. Strict: wrong length, start or end byte, unknown K,
/// non-digit set fields, a bad resolution in `config` and out-of-range targets are errors.
Result<SpidCommand> parse_spid(std::span<const std::uint8_t> frame, const SpidConfig& config = {});

/// The 12-byte Rot2Prog position reply; an error if the position is not finite or does not fit
/// the 4-digit (deg + 360) * 10 field. Angles are rounded to 0.1 degree.
Result<std::array<std::uint8_t, kSpidRot2ReplyBytes>> format_spid_rot2_reply(
    double az_deg, double el_deg, const SpidConfig& config = {});

/// The 5-byte Rot1Prog position reply (azimuth only, whole degrees).
Result<std::array<std::uint8_t, kSpidRot1ReplyBytes>> format_spid_rot1_reply(double az_deg);

/// The 13-byte set frame a client sends for a target (Hamlib's encoding, truncating); for tests
/// and for the simulated client.
Result<SpidFrame> encode_spid_set(double az_deg, double el_deg, const SpidConfig& config = {});

/// Finds 13-byte frames in a byte stream: waits for 'W', and when a candidate frame does not end
/// in 0x20 with a known K, resynchronises at the next 'W'. Bytes skipped are counted. The buffer
/// never holds more than one frame.
class SpidFrameAssembler {
 public:
  std::optional<SpidFrame> push(std::uint8_t byte);
  [[nodiscard]] std::uint64_t dropped_bytes() const { return dropped_bytes_; }
  [[nodiscard]] std::size_t pending_bytes() const { return size_; }

 private:
  void resync();
  SpidFrame buffer_{};
  std::size_t size_ = 0;
  std::uint64_t dropped_bytes_ = 0;
};

}  // namespace azt::proto
