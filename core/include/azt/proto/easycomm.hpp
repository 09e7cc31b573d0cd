#pragma once
// EasyComm I / II (with the EasyComm III GS/GE status queries), server side: azeltrack emulates
// the controller for Hamlib rotctl -m 201/202, Gpredict, Nova, WISP and SatNOGS.
//
// Framing (reference/rotator-controllers-and-protocols.md §8.3): ASCII, a two-letter command plus
// an optional value; commands within a line are separated by spaces; CR or LF ends a line (CRLF
// gives an empty line, which is ignored). A line is answered as a whole: its queries are answered
// in order, space-separated, on one line ending in LF only (gpredict #373), so Hamlib < 4.6's
// "AZ EL" gets "AZ123.4 EL45.0\n" and Hamlib >= 4.6's split "AZ" / "EL" get "AZ123.4\n" and
// "EL45.0\n". Never the K3NG "+123.4". Set-only lines get no reply.
//
// EasyComm I is one set line, "AZaaa.a ELeee.e UPuuuuuuuuu UUU DNddddddddd DDD" (Hamlib sends
// "AZ%.1f EL%.1f UP000 XXX DN000 XXX"); Nova and WISP send "AZxxx.x ELxx.x". It has no queries.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "azt/proto/line_assembler.hpp"
#include "azt/proto/target_limits.hpp"
#include "azt/util/result.hpp"

namespace azt::proto {

enum class EasyCommVersion { One, Two };

enum class EasyCommOp {
  QueryAz,        ///< AZ
  QueryEl,        ///< EL
  SetAz,          ///< AZaaa.a
  SetEl,          ///< ELeee.e
  MoveLeft,       ///< ML
  MoveRight,      ///< MR
  MoveUp,         ///< MU
  MoveDown,       ///< MD
  StopAz,         ///< SA
  StopEl,         ///< SE
  UplinkFreq,     ///< UPnnn (Hz), optionally followed by a mode word (EasyComm I "UUU")
  DownlinkFreq,   ///< DNnnn (Hz), optionally followed by a mode word
  UplinkMode,     ///< UMxxx
  DownlinkMode,   ///< DMxxx
  UplinkRadio,    ///< URxxx
  DownlinkRadio,  ///< DRxxx
  Aos,            ///< AO
  Los,            ///< LO
  Version,        ///< VE
  Status,         ///< GS (EasyComm III status bits)
  Errors,         ///< GE (EasyComm III error bits)
  Park,           ///< PARK (Hamlib)
  Reset,          ///< RESET (Hamlib)
};

struct EasyCommToken {
  EasyCommOp op = EasyCommOp::QueryAz;
  double angle_deg = 0.0;     ///< SetAz / SetEl
  std::uint64_t freq_hz = 0;  ///< UplinkFreq / DownlinkFreq
  std::string text{};         ///< mode or radio word, if any
  bool operator==(const EasyCommToken&) const = default;
};

/// One parsed line: its commands in order (empty for an empty line).
struct EasyCommLine {
  std::vector<EasyCommToken> tokens;
  bool operator==(const EasyCommLine&) const = default;
};

/// The default range of parse_easycomm (az 0..450, el 0..180: the SatNOGS and K3NG controllers'
/// travel). A target outside the range makes the whole line an error.
inline constexpr TargetLimits kEasyCommControllerLimits{0.0, 450.0, 0.0, 180.0};

inline constexpr std::size_t kEasyCommMaxLineChars = 128;
inline constexpr std::size_t kEasyCommMaxTokens = 8;

/// Parses one line (without CR/LF). Strict: unknown commands, malformed numbers (NaN, inf,
/// exponents, junk), out-of-range targets, too many tokens and, for EasyComm I, anything but the
/// set line are errors; nothing of an erroneous line is applied.
Result<EasyCommLine> parse_easycomm(std::string_view line,
                                    EasyCommVersion version = EasyCommVersion::Two,
                                    const TargetLimits& limits = kEasyCommControllerLimits);

/// What the queries report.
struct EasyCommState {
  double az_deg = 0.0;
  double el_deg = 0.0;
  int status_bits = 1;  ///< GS: 1 idle, 2 moving, 4 pointing, 8 error
  int error_bits = 0;   ///< GE: 1 sensor, 2 jam, 4 homing
  std::string_view version = "azeltrack";
};

struct EasyCommReplyOptions {
  /// Report azimuth as 0..360; false reports the raw overlap value.
  bool wrap_az_360 = true;
  /// SatNOGS answers "SA SE" with the position line; Hamlib does not read it.
  bool echo_position_on_stop = false;
};

/// The bytes answering a parsed line: its queries answered on one LF-terminated line, or nothing.
std::string format_easycomm_reply(const EasyCommLine& line, const EasyCommState& state,
                                  const EasyCommReplyOptions& options = {});

/// "AZ123.4" / "EL45.0": one decimal, to_chars, never "-0.0"; empty if not finite.
std::string format_easycomm_angle(std::string_view name, double angle_deg);

/// The assembler for an EasyComm byte stream: CR or LF ends a line.
inline BoundedLineAssembler make_easycomm_assembler() {
  return BoundedLineAssembler(kEasyCommMaxLineChars, "\r\n");
}

}  // namespace azt::proto
