#include "azt/radio/rigctl_reply.hpp"

#include <array>
#include <cstddef>
#include <string>

#include "azt/util/parse_number.hpp"

namespace azt::radio {
namespace {

/// rigctld ends lines with '\n'; a reply through a Windows or serial bridge may keep a '\r'.
std::string_view trimmed(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
  while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
  return line;
}

/// A whole, optionally negative integer of at most 4 digits (Hamlib's codes are 0..22).
std::optional<int> small_integer(std::string_view text) {
  const bool negative = !text.empty() && text.front() == '-';
  if (negative) text.remove_prefix(1);
  if (text.empty() || text.size() > 4) return std::nullopt;
  int value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + (c - '0');
  }
  return negative ? -value : value;
}

/// Hamlib's rig_errcode_e in order (include/hamlib/rig.h:205-227).
constexpr std::array<std::string_view, 23> kErrorNames = {
    "no error (RIG_OK)",
    "invalid parameter (RIG_EINVAL)",
    "invalid configuration (RIG_ECONF)",
    "out of memory (RIG_ENOMEM)",
    "function not implemented (RIG_ENIMPL)",
    "communication timed out (RIG_ETIMEOUT)",
    "I/O error (RIG_EIO)",
    "internal Hamlib error (RIG_EINTERNAL)",
    "protocol error (RIG_EPROTO)",
    "command rejected by the rig (RIG_ERJCTED)",
    "argument truncated (RIG_ETRUNC)",
    "feature not available (RIG_ENAVAIL)",
    "VFO not targetable (RIG_ENTARGET)",
    "bus error (RIG_BUSERROR)",
    "bus collision (RIG_BUSBUSY)",
    "invalid argument (RIG_EARG)",
    "invalid VFO (RIG_EVFO)",
    "argument out of domain (RIG_EDOM)",
    "function deprecated (RIG_EDEPRECATED)",
    "security error (RIG_ESECURITY)",
    "rig not powered on (RIG_EPOWER)",
    "limit exceeded (RIG_ELIMIT)",
    "access denied (RIG_EACCESS)",
};

}  // namespace

std::optional<int> parse_rprt(std::string_view line) {
  line = trimmed(line);
  constexpr std::string_view kPrefix = "RPRT ";
  if (line.substr(0, kPrefix.size()) != kPrefix) return std::nullopt;
  return small_integer(line.substr(kPrefix.size()));
}

std::optional<double> parse_frequency_hz(std::string_view line) {
  const auto hz = parse_finite_double(trimmed(line));
  if (!hz || *hz <= 0.0) return std::nullopt;
  return hz;
}

std::optional<bool> parse_chk_vfo(std::string_view line) {
  line = trimmed(line);
  constexpr std::string_view kOldPrefix = "CHKVFO ";
  if (line.substr(0, kOldPrefix.size()) == kOldPrefix) line.remove_prefix(kOldPrefix.size());
  if (line == "1") return true;
  if (line == "0") return false;
  return std::nullopt;
}

std::string hamlib_error_text(int rprt_code) {
  // Widened before negating: -INT_MIN does not fit an int.
  const long long code = rprt_code < 0 ? -static_cast<long long>(rprt_code) : rprt_code;
  if (code < static_cast<long long>(kErrorNames.size())) {
    return std::string(kErrorNames[static_cast<std::size_t>(code)]);
  }
  return "Hamlib error " + std::to_string(rprt_code);
}

}  // namespace azt::radio
