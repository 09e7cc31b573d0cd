#include "azt/proto/easycomm.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>

namespace azt::proto {
namespace {

/// What may follow a command's letters within its token.
enum class Args { None, AngleOrQuery, Freq, Word };

struct Entry {
  std::string_view text;
  EasyCommOp op;  ///< for AngleOrQuery: the query; the set op is given separately
  EasyCommOp set_op;
  Args args;
  bool in_version_one;
};

constexpr std::array<Entry, 21> kTable{{
    {"PARK", EasyCommOp::Park, EasyCommOp::Park, Args::None, false},
    {"RESET", EasyCommOp::Reset, EasyCommOp::Reset, Args::None, false},
    {"AZ", EasyCommOp::QueryAz, EasyCommOp::SetAz, Args::AngleOrQuery, true},
    {"EL", EasyCommOp::QueryEl, EasyCommOp::SetEl, Args::AngleOrQuery, true},
    {"UP", EasyCommOp::UplinkFreq, EasyCommOp::UplinkFreq, Args::Freq, true},
    {"DN", EasyCommOp::DownlinkFreq, EasyCommOp::DownlinkFreq, Args::Freq, true},
    {"UM", EasyCommOp::UplinkMode, EasyCommOp::UplinkMode, Args::Word, false},
    {"DM", EasyCommOp::DownlinkMode, EasyCommOp::DownlinkMode, Args::Word, false},
    {"UR", EasyCommOp::UplinkRadio, EasyCommOp::UplinkRadio, Args::Word, false},
    {"DR", EasyCommOp::DownlinkRadio, EasyCommOp::DownlinkRadio, Args::Word, false},
    {"ML", EasyCommOp::MoveLeft, EasyCommOp::MoveLeft, Args::None, false},
    {"MR", EasyCommOp::MoveRight, EasyCommOp::MoveRight, Args::None, false},
    {"MU", EasyCommOp::MoveUp, EasyCommOp::MoveUp, Args::None, false},
    {"MD", EasyCommOp::MoveDown, EasyCommOp::MoveDown, Args::None, false},
    {"SA", EasyCommOp::StopAz, EasyCommOp::StopAz, Args::None, false},
    {"SE", EasyCommOp::StopEl, EasyCommOp::StopEl, Args::None, false},
    {"AO", EasyCommOp::Aos, EasyCommOp::Aos, Args::None, false},
    {"LO", EasyCommOp::Los, EasyCommOp::Los, Args::None, false},
    {"VE", EasyCommOp::Version, EasyCommOp::Version, Args::None, false},
    {"GS", EasyCommOp::Status, EasyCommOp::Status, Args::None, false},
    {"GE", EasyCommOp::Errors, EasyCommOp::Errors, Args::None, false},
}};

constexpr std::size_t kMaxValueChars = 16;

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alnum(char c) { return is_digit(c) || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

/// [+-]digits[.digits] only: no exponent, no "nan"/"inf", no spaces.
std::optional<double> parse_angle(std::string_view text) {
  if (text.empty() || text.size() > kMaxValueChars) return std::nullopt;
  bool negative = false;
  if (text.front() == '+' || text.front() == '-') {
    negative = text.front() == '-';
    text.remove_prefix(1);
  }
  std::size_t digits = 0;
  std::size_t dots = 0;
  for (char c : text) {
    if (is_digit(c)) {
      ++digits;
    } else if (c == '.') {
      ++dots;
    } else {
      return std::nullopt;
    }
  }
  if (digits == 0 || dots > 1) return std::nullopt;
  double value = 0.0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::fixed);
  if (ec != std::errc{} || ptr != end || !std::isfinite(value)) return std::nullopt;
  return negative ? -value : value;
}

std::optional<std::uint64_t> parse_freq(std::string_view text) {
  if (text.empty() || text.size() > 12) return std::nullopt;
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc{} || ptr != end) return std::nullopt;
  return value;
}

bool is_word(std::string_view text) {
  if (text.empty() || text.size() > kMaxValueChars) return false;
  for (char c : text) {
    if (!is_alnum(c)) return false;
  }
  return true;
}

const Entry* find_entry(std::string_view token) {
  for (const Entry& entry : kTable) {
    const bool whole_word = entry.text.size() > 2;
    if (whole_word ? token == entry.text : token.substr(0, 2) == entry.text) return &entry;
  }
  return nullptr;
}

Result<EasyCommToken> parse_token(std::string_view token, const Entry& entry,
                                  const TargetLimits& limits) {
  EasyCommToken out{entry.op};
  const std::string_view rest = token.substr(entry.text.size());
  switch (entry.args) {
    case Args::None:
      if (!rest.empty()) return fail("EasyComm: junk after " + std::string(entry.text));
      return out;
    case Args::Word:
      if (!rest.empty() && !is_word(rest)) return fail("EasyComm: bad mode or radio word");
      out.text = std::string(rest);
      return out;
    case Args::Freq: {
      const auto freq = parse_freq(rest);
      if (!freq) return fail("EasyComm: frequency must be digits (Hz)");
      out.freq_hz = *freq;
      return out;
    }
    case Args::AngleOrQuery:
      break;
  }
  if (rest.empty()) return out;  // a query
  const auto angle = parse_angle(rest);
  if (!angle) return fail("EasyComm: malformed angle '" + std::string(rest) + "'");
  const bool az = entry.set_op == EasyCommOp::SetAz;
  if (auto why = az ? limits.why_not_az(*angle) : limits.why_not_el(*angle); !why.empty()) {
    return fail(std::move(why));
  }
  out.op = entry.set_op;
  out.angle_deg = *angle;
  return out;
}

bool is_query(EasyCommOp op) {
  return op == EasyCommOp::QueryAz || op == EasyCommOp::QueryEl || op == EasyCommOp::Version ||
         op == EasyCommOp::Status || op == EasyCommOp::Errors;
}

/// Splits on runs of spaces; returns false if there are more than kEasyCommMaxTokens tokens.
bool split(std::string_view line, std::vector<std::string_view>& out) {
  while (!line.empty()) {
    const auto start = line.find_first_not_of(' ');
    if (start == std::string_view::npos) break;
    line.remove_prefix(start);
    const auto stop = line.find(' ');
    if (out.size() == kEasyCommMaxTokens) return false;
    out.push_back(line.substr(0, stop));
    line.remove_prefix(stop == std::string_view::npos ? line.size() : stop);
  }
  return true;
}

void append_int(std::string& out, long value) {
  std::array<char, 24> buf{};
  auto [ptr, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), value);
  (void)ec;  // 24 chars always hold a long
  out.append(buf.data(), ptr);
}

}  // namespace

Result<EasyCommLine> parse_easycomm(std::string_view line, EasyCommVersion version,
                                    const TargetLimits& limits) {
  if (line.size() > kEasyCommMaxLineChars) return fail("EasyComm: line too long");
  std::vector<std::string_view> words;
  if (!split(line, words)) return fail("EasyComm: too many commands on one line");
  EasyCommLine out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const Entry* entry = find_entry(words[i]);
    if (entry == nullptr) return fail("EasyComm: unknown command '" + std::string(words[i]) + "'");
    if (version == EasyCommVersion::One && !entry->in_version_one) {
      return fail("EasyComm: not an EasyComm I command");
    }
    auto token = parse_token(words[i], *entry, limits);
    if (!token) return token.error();
    if (version == EasyCommVersion::One && is_query(token->op)) {
      return fail("EasyComm: EasyComm I has no queries");
    }
    // EasyComm I: "UP000 XXX" — a mode word that is not a command follows the frequency.
    const bool freq = entry->args == Args::Freq;
    if (freq && i + 1 < words.size() && find_entry(words[i + 1]) == nullptr) {
      if (!is_word(words[i + 1])) return fail("EasyComm: bad mode word");
      token.value().text = std::string(words[++i]);
    }
    out.tokens.push_back(std::move(token).value());
  }
  return out;
}

std::string format_easycomm_angle(std::string_view name, double angle_deg) {
  if (!std::isfinite(angle_deg) || std::fabs(angle_deg) > 1e9) return {};
  long tenths = std::lround(angle_deg * 10.0);
  std::string out(name);
  if (tenths < 0) {
    out.push_back('-');
    tenths = -tenths;
  }
  append_int(out, tenths / 10);
  out.push_back('.');
  append_int(out, tenths % 10);
  return out;
}

std::string format_easycomm_reply(const EasyCommLine& line, const EasyCommState& state,
                                  const EasyCommReplyOptions& options) {
  double az = state.az_deg;
  if (options.wrap_az_360 && std::isfinite(az)) {
    az = std::fmod(az, 360.0);
    if (az < 0.0) az += 360.0;
    if (std::lround(az * 10.0) == 3600) az = 0.0;
  }
  std::string out;
  auto add = [&out](const std::string& field) {
    if (field.empty()) return;  // a non-finite position is not reported
    if (!out.empty()) out.push_back(' ');
    out += field;
  };
  bool stopped = false;
  for (const EasyCommToken& token : line.tokens) {
    switch (token.op) {
      case EasyCommOp::QueryAz:
        add(format_easycomm_angle("AZ", az));
        break;
      case EasyCommOp::QueryEl:
        add(format_easycomm_angle("EL", state.el_deg));
        break;
      case EasyCommOp::Version:
        add("VE" + std::string(state.version));
        break;
      case EasyCommOp::Status:
        add("GS" + std::to_string(state.status_bits));
        break;
      case EasyCommOp::Errors:
        add("GE" + std::to_string(state.error_bits));
        break;
      case EasyCommOp::StopAz:
      case EasyCommOp::StopEl:
        stopped = true;
        break;
      default:
        break;
    }
  }
  if (stopped && out.empty() && options.echo_position_on_stop) {
    add(format_easycomm_angle("AZ", az));
    add(format_easycomm_angle("EL", state.el_deg));
  }
  if (out.empty()) return out;
  out.push_back('\n');
  return out;
}

}  // namespace azt::proto
