#include "azt/proto/rotctld.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "azt/util/parse_number.hpp"

namespace azt::proto {
namespace {

/// Lines longer than this are refused before any copy (the LineAssembler bound, repeated here
/// because parse_rotctld_line takes any string_view).
constexpr std::size_t kMaxLineBytes = LineAssembler::kDefaultMaxLineBytes;
/// Arguments a command may take (M and P take two).
constexpr std::size_t kMaxArgs = 2;
/// `\dump_state` line 1: the protocol version netrotctl checks (rotctl_parse.c dump_state).
constexpr std::string_view kProtocolVersion = "1";
/// `\dump_state` line 2: the model number. netrotctl skips it; 1 is Hamlib's software rotator.
constexpr std::string_view kReportedModel = "1";

/// The command table (reference §8.1): short character ('\0' for long-only), long name, arity.
struct CommandSpec {
  char short_name;
  std::string_view long_name;
  RotctldCommandKind kind;
  std::size_t arity;
};

constexpr std::array<CommandSpec, 10> kCommands{{
    {'P', "set_pos", RotctldCommandKind::SetPos, 2},
    {'p', "get_pos", RotctldCommandKind::GetPos, 0},
    {'S', "stop", RotctldCommandKind::Stop, 0},
    {'K', "park", RotctldCommandKind::Park, 0},
    {'M', "move", RotctldCommandKind::Move, 2},
    {'R', "reset", RotctldCommandKind::Reset, 1},
    {'_', "get_info", RotctldCommandKind::GetInfo, 0},
    {'\0', "dump_state", RotctldCommandKind::DumpState, 0},
    {'q', "quit", RotctldCommandKind::Quit, 0},
    {'Q', "", RotctldCommandKind::Quit, 0},
}};

/// Move keywords accepted besides the numbers (rotator.h ROT_MOVE_*; LEFT is CCW, RIGHT is CW).
struct DirectionName {
  std::string_view name;
  MoveDirection direction;
};

constexpr std::array<DirectionName, 10> kDirectionNames{{
    {"UP", MoveDirection::Up},
    {"DOWN", MoveDirection::Down},
    {"LEFT", MoveDirection::Left},
    {"CCW", MoveDirection::Left},
    {"RIGHT", MoveDirection::Right},
    {"CW", MoveDirection::Right},
    {"UP_LEFT", MoveDirection::UpLeft},
    {"UP_RIGHT", MoveDirection::UpRight},
    {"DOWN_LEFT", MoveDirection::DownLeft},
    {"DOWN_RIGHT", MoveDirection::DownRight},
}};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// ASCII punctuation, as C's ispunct in the "C" locale (no <cctype>: it is locale-dependent).
bool is_punct(char c) {
  return (c >= '!' && c <= '/') || (c >= ':' && c <= '@') || (c >= '[' && c <= '`') ||
         (c >= '{' && c <= '~');
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

/// Hamlib's ERP prefix rule (rotctl_parse.c): punctuation other than `\`, `?`, `_` and `#`.
ResponseMode take_mode(std::string_view& text) {
  if (text.empty()) return {};
  const char c = text.front();
  if (!is_punct(c) || c == '\\' || c == '?' || c == '_' || c == '#') return {};
  text.remove_prefix(1);
  return ResponseMode{true, c == '+' ? '\n' : c};
}

const CommandSpec* find_short(char name) {
  for (const auto& spec : kCommands) {
    if (spec.short_name != '\0' && spec.short_name == name) return &spec;
  }
  return nullptr;
}

const CommandSpec* find_long(std::string_view name) {
  for (const auto& spec : kCommands) {
    if (!spec.long_name.empty() && spec.long_name == name) return &spec;
  }
  return nullptr;
}

/// Splits off the command name; the rest is returned in `text`. Null if unknown.
const CommandSpec* take_command(std::string_view& text) {
  if (text.front() != '\\') {
    const CommandSpec* spec = find_short(text.front());
    text.remove_prefix(1);
    return spec;
  }
  std::size_t end = 1;
  while (end < text.size() && is_name_char(text[end])) ++end;
  const CommandSpec* spec = find_long(text.substr(1, end - 1));
  text.remove_prefix(end);
  return spec;
}

struct Args {
  std::array<std::string_view, kMaxArgs> values{};
  std::size_t count = 0;
  bool too_many = false;
};

Args split_args(std::string_view text) {
  Args args;
  while (true) {
    text = trim(text);
    if (text.empty()) return args;
    std::size_t end = 0;
    while (end < text.size() && !is_space(text[end])) ++end;
    if (args.count == kMaxArgs) {
      args.too_many = true;
      return args;
    }
    args.values[args.count++] = text.substr(0, end);
    text.remove_prefix(end);
  }
}

/// The ERP echo. Argument bytes outside printable ASCII are echoed as '?' so a reply never carries
/// a NUL or an escape sequence back to the client (only lines that fail to parse can hold them).
std::string make_echo(const CommandSpec& spec, const Args& args) {
  std::string echo(spec.long_name.empty() ? std::string_view("quit") : spec.long_name);
  echo += ':';
  for (std::size_t i = 0; i < args.count; ++i) {
    echo += ' ';
    for (const char c : args.values[i]) echo += (c >= ' ' && c <= '~') ? c : '?';
  }
  return echo;
}

/// A finite angle; a comma is a decimal point (Gpredict under a comma locale).
std::optional<double> parse_angle(std::string_view text) {
  std::string dotted(text);
  for (char& c : dotted) {
    if (c == ',') c = '.';
  }
  return parse_finite_double(dotted);
}

std::optional<int> parse_int(std::string_view text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc{} || ptr != end || text.empty()) return std::nullopt;
  return value;
}

std::optional<MoveDirection> parse_direction(std::string_view text) {
  for (const auto& entry : kDirectionNames) {
    if (entry.name == text) return entry.direction;
  }
  const auto number = parse_int(text);
  if (!number) return std::nullopt;
  for (const auto& entry : kDirectionNames) {
    if (static_cast<int>(entry.direction) == *number) return entry.direction;
  }
  return std::nullopt;
}

/// Fills the kind-specific fields; returns an error message or an empty string.
std::string fill_args(RotctldCommand& command, const Args& args, const TargetLimits& limits) {
  switch (command.kind) {
    case RotctldCommandKind::SetPos: {
      const auto az = parse_angle(args.values[0]);
      const auto el = parse_angle(args.values[1]);
      if (!az || !el) return "set_pos needs two finite numbers";
      if (auto why = limits.why_not_az(*az); !why.empty()) return why;
      if (auto why = limits.why_not_el(*el); !why.empty()) return why;
      command.az_deg = *az;
      command.el_deg = *el;
      return {};
    }
    case RotctldCommandKind::Move: {
      const auto direction = parse_direction(args.values[0]);
      const auto speed = parse_int(args.values[1]);
      if (!direction) return "move direction must be 2..256 (a power of two) or a keyword";
      // Hamlib's rotctld passes any speed to the backend, and clients send 0 ("M 16 0"); the
      // speed is ignored here (docs/daemon.md), so every value a client may send is accepted.
      if (!speed || *speed < kMoveSpeedUnchanged || *speed > 100) {
        return "move speed must be 0..100 or -1";
      }
      command.direction = *direction;
      command.speed = *speed;
      return {};
    }
    case RotctldCommandKind::Reset: {
      const auto reset_kind = parse_int(args.values[0]);
      if (!reset_kind) return "reset needs an integer";
      command.reset_kind = *reset_kind;
      return {};
    }
    default:
      return {};
  }
}

RotctldError make_error(int code, const ResponseMode& mode, std::string echo,
                        std::string_view message) {
  return RotctldError{code, mode, std::move(echo), std::string(message)};
}

std::string fixed(double value, int precision) {
  // 309 integer digits for DBL_MAX, sign, point and decimals fit with room to spare.
  std::array<char, 400> buffer{};
  const auto [ptr, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                       std::chars_format::fixed, precision);
  if (ec != std::errc{}) return "0";
  return std::string(buffer.data(), ptr);
}

/// ERP records: echo, then `records`, then `RPRT 0`, joined by the mode's separator.
template <std::size_t N>
std::string extended_reply(const RotctldCommand& command,
                           const std::array<std::string, N>& records) {
  const char separator = command.mode.separator;
  std::string reply = command.echo;
  reply += separator;
  for (const auto& record : records) {
    reply += record;
    reply += separator;
  }
  reply += "RPRT 0\n";
  return reply;
}

}  // namespace

RotctldParseResult parse_rotctld_line(std::string_view line, const TargetLimits& limits) {
  if (line.size() > kMaxLineBytes) {
    return make_error(kRprtInvalid, {}, {}, "line too long");
  }
  std::string_view text = trim(line);
  if (text.empty() || text.front() == '#') return RotctldCommand{};
  const ResponseMode mode = take_mode(text);
  if (text.empty()) return make_error(kRprtNotImplemented, mode, {}, "no command after prefix");
  const CommandSpec* spec = take_command(text);
  if (spec == nullptr) return make_error(kRprtNotImplemented, mode, {}, "unknown command");
  if (!text.empty() && !is_space(text.front())) {
    return make_error(kRprtInvalid, mode, make_echo(*spec, Args{}), "junk after command name");
  }
  const Args args = split_args(text);
  std::string echo = make_echo(*spec, args);
  if (args.too_many || args.count != spec->arity) {
    return make_error(kRprtInvalid, mode, std::move(echo), "wrong number of arguments");
  }
  RotctldCommand command;
  command.kind = spec->kind;
  command.mode = mode;
  command.echo = std::move(echo);
  if (const auto problem = fill_args(command, args, limits); !problem.empty()) {
    return make_error(kRprtInvalid, mode, std::move(command.echo), problem);
  }
  return command;
}

std::string format_rprt(int code, const ResponseMode& mode, std::string_view echo) {
  std::string reply;
  if (mode.extended && !echo.empty()) {
    reply += echo;
    reply += mode.separator;
  }
  reply += "RPRT ";
  reply += std::to_string(code);
  reply += '\n';
  return reply;
}

std::string format_error(const RotctldError& error) {
  return format_rprt(error.code, error.mode, error.echo);
}

std::string format_status(const RotctldCommand& command, int code) {
  return format_rprt(code, command.mode, command.echo);
}

std::string format_get_pos(const RotctldCommand& command, double az_deg, double el_deg) {
  if (!std::isfinite(az_deg) || !std::isfinite(el_deg)) return format_status(command, kRprtIo);
  // Hamlib ≥ 4.0 prints "%.2f"; to_chars with fixed precision rounds the same way, locale-free.
  const std::string az = fixed(az_deg, 2);
  const std::string el = fixed(el_deg, 2);
  if (!command.mode.extended) return az + '\n' + el + '\n';
  return extended_reply(command, std::array<std::string, 2>{"Azimuth: " + az, "Elevation: " + el});
}

std::string format_get_info(const RotctldCommand& command, std::string_view info) {
  // Hamlib's netrotctl reads the reply into a 64-byte buffer (rotctl -m 2 shows 63 characters
  // of a longer one): the info is cut to fit, on a character boundary.
  constexpr std::size_t kMaxInfoChars = 63;
  std::string text(info.substr(0, kMaxInfoChars));
  while (text.size() < info.size() && !text.empty() &&
         (static_cast<unsigned char>(info[text.size()]) & 0xC0U) == 0x80U) {
    text.pop_back();  // never split a UTF-8 sequence
  }
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  if (!command.mode.extended) return text + '\n';
  return extended_reply(command, std::array<std::string, 1>{"Info: " + text});
}

std::string format_dump_state(const RotctldCommand& command, const TargetLimits& limits) {
  // Layout from rotctl_parse.c dump_state (reference §8.1), "%f" = 6 decimals; checked against
  // rotctld -m 1 of Hamlib 4.5.4. The extended form renames some keys but keeps rot_type/done.
  const std::string min_az = fixed(limits.az_min_deg, 6);
  const std::string max_az = fixed(limits.az_max_deg, 6);
  const std::string min_el = fixed(limits.el_min_deg, 6);
  const std::string max_el = fixed(limits.el_max_deg, 6);
  if (!command.mode.extended) {
    std::string reply = std::string(kProtocolVersion) + '\n' + std::string(kReportedModel) + '\n';
    reply += "min_az=" + min_az + "\nmax_az=" + max_az + "\nmin_el=" + min_el +
             "\nmax_el=" + max_el + "\nsouth_zero=0\nrot_type=AzEl\ndone\n";
    return reply;
  }
  return extended_reply(
      command, std::array<std::string, 9>{
                   "rotctld Protocol Ver: " + std::string(kProtocolVersion),
                   "Rotor Model: " + std::string(kReportedModel), "Minimum Azimuth: " + min_az,
                   "Maximum Azimuth: " + max_az, "Minimum Elevation: " + min_el,
                   "Maximum Elevation: " + max_el, "South Zero: 0", "rot_type=AzEl", "done"});
}

LineAssembler::LineAssembler(std::size_t max_line_bytes) : max_line_bytes_(max_line_bytes) {
  line_.reserve(max_line_bytes_);
}

void LineAssembler::reset() {
  line_.clear();
  discarding_ = false;
}

LineAssembler::Pending LineAssembler::accept(char byte) {
  if (byte == '\n' || byte == '\r') {
    if (discarding_) {
      discarding_ = false;
      return Pending::Overlong;
    }
    return line_.empty() ? Pending::None : Pending::Line;
  }
  if (discarding_) return Pending::None;
  if (line_.size() == max_line_bytes_) {
    line_.clear();
    discarding_ = true;
    ++overlong_count_;
    return Pending::None;
  }
  line_ += byte;
  return Pending::None;
}

}  // namespace azt::proto
