#include "azt/proto/gs232.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>

namespace azt::proto {
namespace {

/// What follows a command's letters.
enum class Args { None, Az, AzEl, Speed };

struct Entry {
  std::string_view text;
  Gs232Op op;
  Args args;
};

// Two-character commands come before their one-character prefixes so "C2" is not read as "C".
constexpr std::array<Entry, 22> kTable{{
    {"C2", Gs232Op::QueryAzEl, Args::None},   {"C", Gs232Op::QueryAz, Args::None},
    {"B", Gs232Op::QueryEl, Args::None},      {"M", Gs232Op::GotoAz, Args::Az},
    {"W", Gs232Op::GotoAzEl, Args::AzEl},     {"S", Gs232Op::StopAll, Args::None},
    {"A", Gs232Op::StopAz, Args::None},       {"E", Gs232Op::StopEl, Args::None},
    {"L", Gs232Op::RotateCcw, Args::None},    {"R", Gs232Op::RotateCw, Args::None},
    {"U", Gs232Op::ElevateUp, Args::None},    {"D", Gs232Op::ElevateDown, Args::None},
    {"X", Gs232Op::SetSpeed, Args::Speed},    {"P36", Gs232Op::Mode360, Args::None},
    {"P45", Gs232Op::Mode450, Args::None},    {"Z", Gs232Op::ToggleCentre, Args::None},
    {"H2", Gs232Op::HelpEl, Args::None},      {"H", Gs232Op::Help, Args::None},
    {"O2", Gs232Op::CalElOffset, Args::None}, {"O", Gs232Op::CalAzOffset, Args::None},
    {"F2", Gs232Op::CalElFull, Args::None},   {"F", Gs232Op::CalAzFull, Args::None},
}};

char to_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

bool starts_with_ci(std::string_view line, std::string_view prefix) {
  if (line.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (to_upper(line[i]) != prefix[i]) return false;
  }
  return true;
}

/// Exactly three ASCII digits (Hamlib sends "%03u").
std::optional<int> three_digits(std::string_view text) {
  if (text.size() != 3) return std::nullopt;
  int value = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + 3, value);
  if (ec != std::errc{} || ptr != text.data() + 3 || text.front() == '-' || text.front() == '+') {
    return std::nullopt;
  }
  return value;
}

Result<Gs232Command> parse_args(const Entry& entry, std::string_view rest,
                                const TargetLimits& limits) {
  Gs232Command cmd{entry.op};
  switch (entry.args) {
    case Args::None:
      if (!rest.empty()) return fail("GS-232: junk after command");
      return cmd;
    case Args::Speed:
      if (rest.size() != 1 || rest[0] < '1' || rest[0] > '4') {
        return fail("GS-232: speed must be X1..X4");
      }
      cmd.speed = rest[0] - '0';
      return cmd;
    case Args::Az:
    case Args::AzEl:
      break;
  }
  const auto az = three_digits(rest.substr(0, 3));
  if (!az) return fail("GS-232: azimuth must be three digits");
  if (auto why = limits.why_not_az(*az); !why.empty()) return fail(std::move(why));
  cmd.az_deg = *az;
  rest.remove_prefix(3);
  if (entry.args == Args::Az) {
    if (!rest.empty()) return fail("GS-232: junk after azimuth (timed steps are not supported)");
    return cmd;
  }
  if (rest.size() != 4 || rest[0] != ' ') return fail("GS-232: expected 'Waaa eee'");
  const auto el = three_digits(rest.substr(1));
  if (!el) return fail("GS-232: elevation must be three digits");
  if (auto why = limits.why_not_el(*el); !why.empty()) return fail(std::move(why));
  cmd.el_deg = *el;
  return cmd;
}

/// Appends `value` as at least `width` digits, zero-padded; `value` is >= 0.
void append_padded(std::string& out, long value, int width) {
  std::array<char, 24> buf{};
  auto [ptr, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), value);
  (void)ec;  // 24 chars always hold a long
  const auto digits = static_cast<int>(ptr - buf.data());
  for (int i = digits; i < width; ++i) out.push_back('0');
  out.append(buf.data(), ptr);
}

long report_az(double az_deg, bool wrap) {
  long az = std::lround(az_deg);
  if (wrap) az = ((az % 360) + 360) % 360;
  return az;
}

/// A variant field: "+0aaa" / "-0eee" (§8.2; K3NG sends "-0eee" for negative elevation).
void append_a(std::string& out, long value) {
  out.push_back(value < 0 ? '-' : '+');
  out.push_back('0');
  append_padded(out, value < 0 ? -value : value, 3);
}

/// B variant field: "aaa", or "-eee" when negative (Hamlib reads it with "%d").
void append_b(std::string& out, long value) {
  if (value < 0) out.push_back('-');
  append_padded(out, value < 0 ? -value : value, 3);
}

std::string position_reply(Gs232Op op, long az, long el, const Gs232ReplyOptions& options) {
  std::string out;
  const bool b = options.variant == Gs232Variant::B;
  if (op != Gs232Op::QueryEl) {
    if (b) {
      out += "AZ=";
      append_b(out, az);
    } else {
      append_a(out, az);
    }
  }
  if (op == Gs232Op::QueryAzEl && b) out += options.b_separator;
  if (op != Gs232Op::QueryAz) {
    if (b) {
      out += "EL=";
      append_b(out, el);
    } else {
      append_a(out, el);
    }
  }
  out += "\r\n";
  return out;
}

}  // namespace

Result<Gs232Command> parse_gs232(std::string_view line, const TargetLimits& limits) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.size() > kGs232MaxLineChars) return fail("GS-232: line too long");
  if (line.empty()) return Gs232Command{Gs232Op::Empty};
  for (const Entry& entry : kTable) {
    if (!starts_with_ci(line, entry.text)) continue;
    // The first matching entry decides (longer commands precede their prefixes in the table).
    return parse_args(entry, line.substr(entry.text.size()), limits);
  }
  return fail("GS-232: unknown command");
}

std::string format_gs232_reply(const Gs232Command& command, double az_deg, double el_deg,
                               const Gs232ReplyOptions& options) {
  switch (command.op) {
    case Gs232Op::Empty:
      return {};
    case Gs232Op::QueryAz:
    case Gs232Op::QueryEl:
    case Gs232Op::QueryAzEl:
      if (!std::isfinite(az_deg) || !std::isfinite(el_deg) || std::fabs(az_deg) > 1e6 ||
          std::fabs(el_deg) > 1e6) {
        return format_gs232_error();
      }
      return position_reply(command.op, report_az(az_deg, options.wrap_az_360), std::lround(el_deg),
                            options);
    case Gs232Op::Help:
      return "C C2 B Maaa Waaa eee S A E L R U D X1-X4 P36 P45 Z O F\r\n";
    case Gs232Op::HelpEl:
      return "B Waaa eee U D E O2 F2\r\n";
    default:
      return "\r";
  }
}

std::string format_gs232_error() { return "?>\r\n"; }

}  // namespace azt::proto
