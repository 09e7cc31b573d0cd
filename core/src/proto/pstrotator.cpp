#include "azt/proto/pstrotator.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <system_error>

#include "azt/util/parse_number.hpp"

namespace azt::proto {
namespace {

/// Longest tag name and value kept (QRA locators are 4-10 characters, numbers under 20).
constexpr std::size_t kMaxNameChars = 16;
constexpr std::size_t kMaxValueChars = 32;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
char to_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

bool equals_ci(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (to_upper(a[i]) != to_upper(b[i])) return false;
  }
  return true;
}

/// Removes `prefix` (matched case-insensitively) from the front of `text`, if it is there.
bool take_ci(std::string_view& text, std::string_view prefix) {
  if (text.size() < prefix.size() || !equals_ci(text.substr(0, prefix.size()), prefix)) {
    return false;
  }
  text.remove_prefix(prefix.size());
  return true;
}

/// The numeric prefix `[+-]digits[.digits]`, then only a `.digits` tail (Hamlib's "%f.2").
std::optional<double> parse_lenient_angle(std::string_view text) {
  text = trim(text);
  std::size_t end = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
  const std::size_t first_digit = end;
  while (end < text.size() && is_digit(text[end])) ++end;
  if (end == first_digit) return std::nullopt;
  if (end < text.size() && text[end] == '.') {
    ++end;
    while (end < text.size() && is_digit(text[end])) ++end;
  }
  std::string_view tail = text.substr(end);
  if (!tail.empty()) {
    if (tail.front() != '.') return std::nullopt;
    tail.remove_prefix(1);
    for (const char c : tail) {
      if (!is_digit(c)) return std::nullopt;
    }
  }
  return parse_finite_double(text.substr(0, end));
}

/// A flag value: "0" or "1".
std::optional<bool> parse_flag(std::string_view text) {
  text = trim(text);
  if (text == "1") return true;
  if (text == "0") return false;
  return std::nullopt;
}

bool is_locator(std::string_view text) {
  text = trim(text);
  if (text.empty() || text.size() > 10) return false;
  for (const char c : text) {
    if (!is_alpha(c) && !is_digit(c)) return false;
  }
  return true;
}

/// Applies `<name>value</name>` to `command`; an error names what was wrong.
std::optional<std::string> apply_tag(std::string_view name, std::string_view value,
                                     const TargetLimits& limits, PstCommand& command) {
  if (equals_ci(name, "AZIMUTH") || equals_ci(name, "ELEVATION")) {
    const bool az = equals_ci(name, "AZIMUTH");
    const auto angle = parse_lenient_angle(value);
    if (!angle) return "PstRotator: malformed angle '" + std::string(value) + "'";
    if (auto why = az ? limits.why_not_az(*angle) : limits.why_not_el(*angle); !why.empty()) {
      return why;
    }
    (az ? command.az_deg : command.el_deg) = *angle;
    return std::nullopt;
  }
  if (equals_ci(name, "STOP") || equals_ci(name, "PARK") || equals_ci(name, "TRACK") ||
      equals_ci(name, "ON")) {
    const auto flag = parse_flag(value);
    if (!flag) return "PstRotator: " + std::string(name) + " must be 0 or 1";
    if (equals_ci(name, "STOP")) command.stop = command.stop || *flag;
    if (equals_ci(name, "PARK")) command.park = command.park || *flag;
    return std::nullopt;
  }
  if (equals_ci(name, "QRA")) {
    if (!is_locator(value)) return std::string("PstRotator: bad QRA locator");
    return std::nullopt;
  }
  return "PstRotator: unknown tag '" + std::string(name) + "'";
}

/// Takes one `<NAME>value</NAME>` item from the front of `text`.
std::optional<std::string> take_tag(std::string_view& text, const TargetLimits& limits,
                                    PstCommand& command) {
  const auto close = text.find('>');
  if (close == std::string_view::npos) return std::string("PstRotator: unclosed tag");
  const std::string_view name = text.substr(1, close - 1);
  if (name.empty() || name.size() > kMaxNameChars) return std::string("PstRotator: bad tag");
  for (const char c : name) {
    if (!is_alpha(c)) return std::string("PstRotator: bad tag");
  }
  text.remove_prefix(close + 1);
  const auto end = text.find("</");
  if (end == std::string_view::npos) return "PstRotator: missing </" + std::string(name) + ">";
  if (end > kMaxValueChars) return "PstRotator: <" + std::string(name) + "> value too long";
  const std::string_view value = text.substr(0, end);
  text.remove_prefix(end + 2);
  if (!take_ci(text, name) || text.empty() || text.front() != '>') {
    return "PstRotator: <" + std::string(name) + "> closed by another tag";
  }
  text.remove_prefix(1);
  return apply_tag(name, value, limits, command);
}

/// Takes one bare `AZ?` or `EL?` from the front of `text`.
std::optional<std::string> take_query(std::string_view& text, PstCommand& command) {
  if (take_ci(text, "AZ?")) {
    command.query_az = true;
  } else if (take_ci(text, "EL?")) {
    command.query_el = true;
  } else {
    return std::string("PstRotator: unknown command");
  }
  return std::nullopt;
}

}  // namespace

Result<PstCommand> parse_pstrotator(std::string_view datagram, const TargetLimits& limits) {
  if (datagram.size() > kPstMaxDatagramBytes) return fail("PstRotator: datagram too long");
  std::string_view text = trim(datagram);
  if (!take_ci(text, "<PST>")) return fail("PstRotator: datagram must start with <PST>");
  if (text.size() < 6 || !equals_ci(text.substr(text.size() - 6), "</PST>")) {
    return fail("PstRotator: datagram must end with </PST>");
  }
  text.remove_suffix(6);
  PstCommand command;
  while (!(text = trim(text)).empty()) {
    const auto problem =
        text.front() == '<' ? take_tag(text, limits, command) : take_query(text, command);
    if (problem) return fail(*problem);
  }
  return command;
}

std::string format_pstrotator_angle(std::string_view name, double deg) {
  if (!std::isfinite(deg) || std::fabs(deg) > 1e9) return {};
  double tenths = std::round(deg * 10.0) / 10.0;
  if (tenths == 0.0) tenths = 0.0;  // -0.0 compares equal to 0.0; this clears its sign
  std::array<char, 32> buffer{};
  const auto [ptr, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), tenths,
                                       std::chars_format::fixed, 1);
  if (ec != std::errc{}) return {};
  std::string out(name);
  out += ':';
  out.append(buffer.data(), ptr);
  out += '\r';
  return out;
}

std::string handle_pstrotator_datagram(std::string_view datagram, RotatorService& service,
                                       std::string_view client, const TargetLimits& limits) {
  service.activity(client);
  const auto command = parse_pstrotator(datagram, limits);
  if (!command) {
    service.refused(client, command.error().message);
    return {};
  }
  if (command->stop) service.stop(client, std::nullopt);
  if (command->az_deg && command->el_deg) {
    service.goto_position(client, *command->az_deg, *command->el_deg);
  } else if (command->az_deg) {
    service.goto_axis(client, Axis::Az, *command->az_deg);
  } else if (command->el_deg) {
    service.goto_axis(client, Axis::El, *command->el_deg);
  }
  if (command->park) service.park(client);
  if (!command->query_az && !command->query_el) return {};
  const auto position = service.position();
  if (!position) return {};
  std::string reply;
  if (command->query_az) reply += format_pstrotator_angle("AZ", position->az_deg);
  if (command->query_el) reply += format_pstrotator_angle("EL", position->el_deg);
  return reply;
}

}  // namespace azt::proto
