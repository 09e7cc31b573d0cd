#include "azt/software/update_status.hpp"

#include <array>
#include <charconv>
#include <optional>
#include <utility>

#include "azt/util/text_lines.hpp"

namespace azt::software {
namespace {

constexpr std::array<std::pair<UpdatePhase, std::string_view>, 5> kPhases{{
    {UpdatePhase::Checking, "checking"},
    {UpdatePhase::Refused, "refused"},
    {UpdatePhase::Installing, "installing"},
    {UpdatePhase::Installed, "installed"},
    {UpdatePhase::Failed, "failed"},
}};
constexpr std::size_t kMaxStatusBytes = std::size_t{16} * 1024;
constexpr std::size_t kMaxFieldBytes = 1024;

std::optional<std::int64_t> integer(std::string_view text) {
  std::int64_t value = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

bool is_hex_sha256(std::string_view text) {
  if (text.size() != 64) return false;
  for (const char c : text) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

/// A Debian version's characters (deb-version(7)): nothing that could mislead a reader.
bool is_version(std::string_view text) {
  if (text.size() > 128) return false;
  for (const char c : text) {
    const bool alnum = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!alnum && std::string_view(".+-~:").find(c) == std::string_view::npos) return false;
  }
  return true;
}

std::optional<UpdatePhase> phase_named(std::string_view name) {
  for (const auto& [phase, text] : kPhases) {
    if (text == name) return phase;
  }
  return std::nullopt;
}

/// Sets the field `key` names from `value`; false when the value is not one that key takes.
bool set_field(UpdateStatus& s, std::string_view key, std::string_view value, bool& has_phase) {
  if (key == "phase") {
    const auto phase = phase_named(value);
    if (phase) s.phase = *phase;
    has_phase = phase.has_value();
    return has_phase;
  }
  if (key == "percent") {
    const auto p = integer(value);
    if (p) s.percent = static_cast<int>(*p);
    return p && *p >= 0 && *p <= 100;
  }
  if (key == "at") {
    const auto t = integer(value);
    if (t) s.at_unix_s = *t;
    return t && *t >= 0;
  }
  if (key == "sha256") {
    s.sha256_hex = std::string(value);
    return value.empty() || is_hex_sha256(value);
  }
  if (key == "from" || key == "to") {
    (key == "from" ? s.from_version : s.to_version) = std::string(value);
    return is_version(value);
  }
  if (key == "message") s.message = std::string(value);
  if (key == "signer") s.signer = std::string(value);
  return true;  // the message is any text; unknown keys are a newer helper's
}

}  // namespace

std::string_view to_string(UpdatePhase phase) {
  for (const auto& [p, text] : kPhases) {
    if (p == phase) return text;
  }
  return "?";
}

bool finished(UpdatePhase phase) {
  return phase == UpdatePhase::Refused || phase == UpdatePhase::Installed ||
         phase == UpdatePhase::Failed;
}

Result<UpdateStatus> parse_update_status(std::string_view text) {
  if (text.size() > kMaxStatusBytes) return fail("the update status is over 16 KiB");
  UpdateStatus status;
  bool has_phase = false;
  int line_number = 0;
  for (const std::string_view line : split_lines(text)) {
    ++line_number;
    if (line.empty()) continue;
    const auto eq = line.find('=');
    const std::string where = "update status line " + std::to_string(line_number);
    if (eq == std::string_view::npos) return fail(where + ": no '='");
    if (line.size() - eq - 1 > kMaxFieldBytes) return fail(where + ": value over 1 KiB");
    const std::string_view key = line.substr(0, eq);
    if (!set_field(status, key, line.substr(eq + 1), has_phase)) {
      return fail(where + ": bad " + std::string(key));
    }
  }
  if (!has_phase) return fail("the update status names no phase");
  return status;
}

}  // namespace azt::software
