#include "schedule/hook_report.hpp"

#include <string_view>

#include "azt/util/format_number.hpp"
#include "azt/util/valid_utf8.hpp"

namespace azt::app {
namespace {

/// Control characters (an escape sequence for the operator's terminal, a carriage return that
/// hides what came before) become '?'; lines are joined, the last newline dropped.
std::string one_line(std::string_view text) {
  while (!text.empty() && text.back() == '\n') text.remove_suffix(1);
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += " | ";
    } else if (byte < 0x20 || byte == 0x7f) {
      out += c == '\t' ? ' ' : '?';
    } else {
      out += c;
    }
  }
  return valid_utf8(out);
}

/// `text` cut to at most `max_bytes`, not inside a UTF-8 sequence.
std::string cut(std::string text, std::size_t max_bytes) {
  if (text.size() <= max_bytes) return text;
  std::size_t end = max_bytes;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0U) == 0x80U) --end;
  text.resize(end);
  return text + " …";
}

}  // namespace

std::string hook_ending(const linux_os::ChildResult& result, double timeout_s) {
  if (!result.spawn_error.empty()) return "did not run: " + valid_utf8(result.spawn_error);
  if (result.stopped) return "stopped: the daemon is stopping";
  if (result.timed_out) return "killed after its " + format_number(timeout_s) + " s timeout";
  const std::string in = " in " + format_fixed(result.duration_s, 2) + " s";
  if (result.signal != 0) return "ended by signal " + std::to_string(result.signal) + in;
  return "exited " + std::to_string(result.exit_code) + in;
}

bool hook_succeeded(const linux_os::ChildResult& result) {
  return result.spawn_error.empty() && !result.stopped && !result.timed_out && result.signal == 0 &&
         result.exit_code == 0;
}

std::string hook_output(const linux_os::ChildResult& result, std::size_t max_bytes) {
  std::string out = cut(one_line(result.first_lines), max_bytes);
  if (result.dropped_bytes > 0) {
    out += " (+" + std::to_string(result.dropped_bytes) + " bytes not kept)";
  }
  return out;
}

}  // namespace azt::app
