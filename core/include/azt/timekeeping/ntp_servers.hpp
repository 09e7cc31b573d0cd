#pragma once
// The seed's "NTP Client Server" setting (docs/time.md): the upstream NTP servers the operator
// types, checked strictly because they end up as lines of chrony's configuration (a newline or
// a space in a name would be a directive of the operator's choosing), and the chrony sources
// file azeltrack writes for them (chrony.conf(5), "sourcedir").

#include <string>
#include <string_view>
#include <vector>

#include "azt/util/result.hpp"

namespace azt::timekeeping {

inline constexpr std::size_t kMaxNtpServers = 8;

/// A host name (RFC 1123 labels: letters, digits, hyphens, dots; at most 253 characters) or an
/// IPv4 or IPv6 address; anything else is an error saying what is wrong.
Result<std::string> check_ntp_server(std::string_view text);
/// Every name checked, none twice, at most kMaxNtpServers (none: chrony keeps its other sources).
Result<std::vector<std::string>> check_ntp_servers(const std::vector<std::string>& names);

/// The sources file: a comment, then `server NAME iburst` per server (`pool NAME iburst` for a
/// pool.ntp.org name, which stands for several servers).
std::string chrony_sources_text(const std::vector<std::string>& servers);
/// The servers named in a sources file (its `server` and `pool` lines), in order.
std::vector<std::string> servers_in_sources(std::string_view text);

}  // namespace azt::timekeeping
