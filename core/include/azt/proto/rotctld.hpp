#pragma once
// Hamlib rotctld text protocol (TCP, default port 4533): a pure, line-oriented codec.
//
// Grammar, replies and client quirks follow reference/rotator-controllers-and-protocols.md §8.1
// (sources there: Hamlib/Hamlib tests/rotctl_parse.c, tests/rotctld.c, rigs/dummy/netrotctl.c;
// csete/gpredict src/gtk-rot-ctrl.c). The reply bytes were checked against a real
// `rotctld -m 1` (Hamlib 4.5.4, Debian 12); the unit tests hold those transcripts.
//
// One line holds one command: a short character (`P`, `p`, `S`, `K`, `M`, `R`, `_`, `q`, `Q`) or
// `\` plus a long name (`\set_pos`, `\get_pos`, `\stop`, `\park`, `\move`, `\reset`, `\get_info`,
// `\dump_state`), then whitespace-separated arguments. An optional punctuation prefix (`+`, `;`,
// `|`, `,` ...) selects Hamlib's extended response protocol (ERP): `+` ends every record with a
// newline, any other prefix character separates the records and only the final `RPRT n` ends with a
// newline. Gpredict may send comma decimals (`P 123,45 10,00`); a comma is read as a decimal point
// (Hamlib commit 2deeca86d).
//
// Deliberate deviations from Hamlib (documented for users in the rotctld server docs):
//   - An unknown command is answered with `RPRT -4` (ENIMPL); Hamlib sends nothing.
//   - NaN, infinities, a missing or extra argument, and trailing junk are answered with
//     `RPRT -1` (EINVAL); Hamlib 4.5 accepts `P nan 2` and reads `P 1 2 3` as `P 1 2` then `3`.
//   - An out-of-range `P` target is answered with `RPRT -1` (EINVAL), as Hamlib ≤ 4.5 does (Hamlib
//     4.6 answers -21, ELIMIT); every non-zero code is an error to Gpredict and netrotctl.
//   - Empty lines and `#` comment lines get no reply, as in Hamlib.
//   - The ERP echo shows argument bytes outside printable ASCII as `?` (Hamlib echoes them raw), so
//     no reply carries a NUL or an escape sequence; only lines that fail to parse hold such bytes.

#include <cstddef>
#include <string>
#include <string_view>
#include <variant>

#include "azt/proto/target_limits.hpp"

namespace azt::proto {

/// Hamlib error codes as sent on the wire (include/hamlib/rig.h, sent negated; reference §8.1).
inline constexpr int kRprtOk = 0;
inline constexpr int kRprtInvalid = -1;         ///< RIG_EINVAL: invalid parameter
inline constexpr int kRprtNotImplemented = -4;  ///< RIG_ENIMPL: not implemented
inline constexpr int kRprtIo = -6;              ///< RIG_EIO: I/O error (e.g. position unreadable)
inline constexpr int kRprtRejected = -9;        ///< RIG_ERJCTED: command rejected (e.g. faulted)
inline constexpr int kRprtLimit = -21;          ///< RIG_ELIMIT: limit exceeded (Hamlib ≥ 4.6)

/// How a reply is framed. Plain is Hamlib's default mode; extended echoes the command first and
/// ends with `RPRT n`. `separator` is '\n' for the `+` prefix, otherwise the prefix character.
struct ResponseMode {
  bool extended = false;
  char separator = '\n';
};

enum class RotctldCommandKind {
  SetPos,     ///< P / \set_pos  az el
  GetPos,     ///< p / \get_pos
  Stop,       ///< S / \stop
  Park,       ///< K / \park
  Move,       ///< M / \move     direction speed
  Reset,      ///< R / \reset    reset-kind (1 = all)
  GetInfo,    ///< _ / \get_info
  DumpState,  ///< \dump_state   (rotctl -m 2 and other netrotctl clients send it on connect)
  Quit,       ///< q / Q         the server closes the connection; no reply
  Ignore,     ///< empty line or `#` comment: no reply
};

/// Hamlib's move directions (include/hamlib/rotator.h ROT_MOVE_*).
enum class MoveDirection {
  Up = 2,
  Down = 4,
  Left = 8,    ///< counter-clockwise
  Right = 16,  ///< clockwise
  UpLeft = 32,
  UpRight = 64,
  DownLeft = 128,
  DownRight = 256,
};

/// `M` speed meaning "keep the current speed".
inline constexpr int kMoveSpeedUnchanged = -1;

/// A parsed, validated command. Fields not used by `kind` keep their defaults.
struct RotctldCommand {
  RotctldCommandKind kind = RotctldCommandKind::Ignore;
  ResponseMode mode;
  std::string echo;  ///< ERP first record, e.g. "set_pos: 90 45" (long name, args as received)
  double az_deg = 0.0;
  double el_deg = 0.0;
  MoveDirection direction = MoveDirection::Up;
  int speed = kMoveSpeedUnchanged;  ///< 1..100, or kMoveSpeedUnchanged
  int reset_kind = 0;
};

/// A line that must be answered with `RPRT code` (in the line's response mode).
struct RotctldError {
  int code = kRprtInvalid;
  ResponseMode mode;
  std::string echo;     ///< ERP first record when the command name was known, else empty
  std::string message;  ///< why, for logs
};

using RotctldParseResult = std::variant<RotctldCommand, RotctldError>;

/// Parses one line (without its terminator). Pure and locale-free.
/// `limits` is the travel enforced on `P` (and announced by `\dump_state`).
RotctldParseResult parse_rotctld_line(std::string_view line, const TargetLimits& limits);

/// `RPRT code` for a command without output (P, S, K, M, R) or for a failed command.
std::string format_rprt(int code, const ResponseMode& mode, std::string_view echo);
/// The reply to a parse error.
std::string format_error(const RotctldError& error);
/// The reply to a command that succeeded or failed with `code` and has no data (P, S, K, M, R).
std::string format_status(const RotctldCommand& command, int code);
/// The `p` reply, "%.2f\n%.2f\n" in plain mode, written as one string so a server can send it in
/// one write (Gpredict reads it with one recv). Non-finite angles give `RPRT -6` (EIO).
std::string format_get_pos(const RotctldCommand& command, double az_deg, double el_deg);
/// The `_` reply: the info text (one line; line breaks in it are replaced by spaces).
std::string format_get_info(const RotctldCommand& command, std::string_view info);
/// The `\dump_state` reply that netrotctl (`rotctl -m 2`) parses on connect.
std::string format_dump_state(const RotctldCommand& command, const TargetLimits& limits);

/// What LineAssembler hands to its callback.
enum class LineStatus {
  Complete,  ///< a line, terminator removed
  Overlong,  ///< a line longer than the bound was dropped; the view is empty; answer RPRT -1
};

/// Splits a byte stream into lines. CR, LF and CRLF all end a line (Hamlib reads CR as
/// whitespace, so `p\r` works there too); empty lines are not delivered. Holds at most
/// `max_line_bytes` bytes: a longer line is dropped up to its terminator and reported once.
class LineAssembler {
 public:
  static constexpr std::size_t kDefaultMaxLineBytes = 256;

  explicit LineAssembler(std::size_t max_line_bytes = kDefaultMaxLineBytes);

  /// Calls `on_line(std::string_view line, LineStatus status)` for every line that `bytes`
  /// completes, in order. The view is valid only during the call.
  template <typename OnLine>
  void feed(std::string_view bytes, OnLine&& on_line) {
    for (const char byte : bytes) {
      if (const auto status = accept(byte); status != Pending::None) {
        on_line(std::string_view(line_),
                status == Pending::Line ? LineStatus::Complete : LineStatus::Overlong);
        line_.clear();
      }
    }
  }

  [[nodiscard]] std::size_t overlong_count() const { return overlong_count_; }
  [[nodiscard]] std::size_t buffered_bytes() const { return line_.size(); }
  /// Forgets a partial line (e.g. when the connection is reused).
  void reset();

 private:
  enum class Pending { None, Line, Overlong };
  Pending accept(char byte);

  std::size_t max_line_bytes_;
  std::string line_;
  bool discarding_ = false;
  std::size_t overlong_count_ = 0;
};

}  // namespace azt::proto
