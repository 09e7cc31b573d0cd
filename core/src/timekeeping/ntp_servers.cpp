#include "azt/timekeeping/ntp_servers.hpp"

#include <algorithm>

#include "azt/util/quote.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::timekeeping {
namespace {

constexpr std::size_t kMaxNameChars = 253;  // RFC 1035 §2.3.4, without the final dot
constexpr std::size_t kMaxLabelChars = 63;
constexpr std::size_t kMaxIpv6Chars = 45;

bool is_alnum(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

bool is_hex_or_colon(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F') || c == ':' ||
         c == '.';
}

bool valid_label(std::string_view label) {
  if (label.empty() || label.size() > kMaxLabelChars) return false;
  if (label.front() == '-' || label.back() == '-') return false;
  return std::all_of(label.begin(), label.end(), [](char c) { return is_alnum(c) || c == '-'; });
}

bool valid_host_name(std::string_view name) {
  if (name.size() > kMaxNameChars) return false;
  std::size_t start = 0;
  while (true) {
    const auto dot = name.find('.', start);
    if (!valid_label(name.substr(start, dot == std::string_view::npos ? name.npos : dot - start))) {
      return false;
    }
    if (dot == std::string_view::npos) return true;
    start = dot + 1;
  }
}

bool valid_ipv6(std::string_view text) {
  return text.size() <= kMaxIpv6Chars && std::count(text.begin(), text.end(), ':') >= 2 &&
         std::all_of(text.begin(), text.end(), is_hex_or_colon);
}

bool is_pool(std::string_view name) {
  constexpr std::string_view kPool = "pool.ntp.org";
  return name.size() >= kPool.size() && name.substr(name.size() - kPool.size()) == kPool;
}

/// "server NAME …" / "pool NAME …" -> NAME; "" for any other line.
std::string source_name(std::string_view line) {
  line = trim(line);
  const std::string_view word = line.substr(0, line.find_first_of(" \t"));
  if (word != "server" && word != "pool") return "";
  const std::string_view rest = trim(line.substr(word.size()));
  return std::string(rest.substr(0, rest.find_first_of(" \t")));
}

}  // namespace

Result<std::string> check_ntp_server(std::string_view text) {
  const std::string_view name = trim(text);
  if (name.empty()) return fail("an NTP server needs a name or an address");
  if (valid_ipv6(name) || valid_host_name(name)) return std::string(name);
  return fail("not a host name or an IP address: " + quote(name) +
              " (letters, digits, '-' and '.' only)");
}

Result<std::vector<std::string>> check_ntp_servers(const std::vector<std::string>& names) {
  if (names.size() > kMaxNtpServers) {
    return fail("at most " + std::to_string(kMaxNtpServers) + " NTP servers");
  }
  std::vector<std::string> out;
  for (const auto& name : names) {
    auto checked = check_ntp_server(name);
    if (!checked) return checked.error();
    if (std::find(out.begin(), out.end(), checked.value()) != out.end()) {
      return fail(quote(checked.value()) + " is named twice");
    }
    out.push_back(std::move(checked).value());
  }
  return out;
}

std::string chrony_sources_text(const std::vector<std::string>& servers) {
  std::string text =
      "# The upstream NTP servers set on azeltrack's console (its [time] manage_chrony).\n"
      "# azeltrack rewrites this file whole: change the servers there, not here.\n";
  for (const auto& name : servers) {
    text += std::string(is_pool(name) ? "pool " : "server ") + name + " iburst\n";
  }
  return text;
}

std::vector<std::string> servers_in_sources(std::string_view text) {
  std::vector<std::string> servers;
  for (const auto line : split_lines(text)) {
    std::string name = source_name(line);
    if (!name.empty()) servers.push_back(std::move(name));
  }
  return servers;
}

}  // namespace azt::timekeeping
