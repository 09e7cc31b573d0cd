#pragma once
// Yaesu GS-232A / GS-232B, server side: azeltrack emulates the controller for PC programs
// (Hamlib rotctl -m 601/603, PstRotator, SatPC32).
//
// Framing (reference/rotator-controllers-and-protocols.md §8.2): commands end in CR, are
// case-insensitive, LF is ignored (so CRLF is one terminator) and an empty line is ignored
// silently: Hamlib >= 4.0 sends "W123 045\r\r" to a GS-232B and must not get "?>" back. Angles are
// exactly three zero-padded digits. The controller does not echo; it returns CR after every
// command plus LF when data was returned. An invalid command returns "?>\r\n".
//
// Replies differ by variant (§8.2 table and server test vectors):
//   C2  A: "+0123+0045\r\n"      B: "AZ=123  EL=045\r\n" (two spaces, real GS-232B / RTC-200)
//   C   A: "+0123\r\n"           B: "AZ=123\r\n"
//   B   A: "+0045\r\n"           B: "EL=045\r\n"
// Hamlib's GS-232B reader needs at least 10 characters and integers only, so B replies are
// always integers and C2 always carries both axes.

#include <string>
#include <string_view>

#include "azt/proto/line_assembler.hpp"
#include "azt/proto/target_limits.hpp"
#include "azt/util/result.hpp"

namespace azt::proto {

enum class Gs232Variant { A, B };

enum class Gs232Op {
  Empty,         ///< an empty line: ignored, no reply
  QueryAz,       ///< C
  QueryAzEl,     ///< C2
  QueryEl,       ///< B
  GotoAz,        ///< Maaa
  GotoAzEl,      ///< Waaa eee
  StopAll,       ///< S
  StopAz,        ///< A
  StopEl,        ///< E
  RotateCcw,     ///< L
  RotateCw,      ///< R
  ElevateUp,     ///< U
  ElevateDown,   ///< D
  SetSpeed,      ///< X1..X4
  Mode360,       ///< P36
  Mode450,       ///< P45
  ToggleCentre,  ///< Z
  Help,          ///< H
  HelpEl,        ///< H2
  CalAzOffset,   ///< O
  CalAzFull,     ///< F
  CalElOffset,   ///< O2
  CalElFull,     ///< F2
};

/// One parsed command. Angles are whole degrees as sent; speed is 1 (slowest) .. 4.
struct Gs232Command {
  Gs232Op op = Gs232Op::Empty;
  int az_deg = 0;
  int el_deg = 0;
  int speed = 0;
  bool operator==(const Gs232Command&) const = default;
};

/// What a real GS-232 controller takes (az 0..450 on a 450° rotator, el 0..180 on a G-5500 with
/// flip-over): the default range of parse_gs232. Targets outside the range are parse errors ("?>");
/// the whole-degree targets are compared as doubles.
inline constexpr TargetLimits kGs232ControllerLimits{0.0, 450.0, 0.0, 180.0};

/// Longest command line kept (timed-step lists are not supported, so lines are short).
inline constexpr std::size_t kGs232MaxLineChars = 64;

/// Parses one line without its CR (a stray trailing CR is tolerated). Strict: unknown commands,
/// wrong digit counts, out-of-range targets and trailing junk are errors.
Result<Gs232Command> parse_gs232(std::string_view line,
                                 const TargetLimits& limits = kGs232ControllerLimits);

struct Gs232ReplyOptions {
  Gs232Variant variant = Gs232Variant::B;
  /// Separator between the B-variant C2 fields: two spaces on real units; K3NG sends none.
  std::string_view b_separator = "  ";
  /// Report azimuth as 0..359 (what real Yaesu does, K3NG #40); false reports raw 0..450.
  bool wrap_az_360 = true;
};

/// The bytes answering `command` given the current position: position replies for C/C2/B, "\r"
/// for set and motion commands, nothing for an empty line, help text for H/H2.
/// Non-finite positions answer "?>\r\n" (the controller cannot report).
std::string format_gs232_reply(const Gs232Command& command, double az_deg, double el_deg,
                               const Gs232ReplyOptions& options = {});

/// The reply to any line that failed to parse.
std::string format_gs232_error();

/// The assembler for a GS-232 byte stream: CR ends a line, LF is ignored.
inline BoundedLineAssembler make_gs232_assembler() {
  return BoundedLineAssembler(kGs232MaxLineChars, "\r", "\n");
}

}  // namespace azt::proto
