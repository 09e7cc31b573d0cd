#pragma once

#include <string>
#include <string_view>

namespace azt {

/// `text` as valid UTF-8: every byte sequence that is not well-formed UTF-8 (Unicode 15 §3.9,
/// table 3-7: no overlongs, no surrogates, nothing above U+10FFFF) becomes U+FFFD, one per
/// maximal ill-formed subpart as the standard recommends. Text from outside (HTTP headers,
/// catalogue names, files) goes through this before it reaches JSON or a log line, where an
/// invalid byte would throw (nlohmann::json::dump) or corrupt the output.
std::string valid_utf8(std::string_view text);

/// Whether `text` is well-formed UTF-8 (valid_utf8 would return it unchanged).
bool is_valid_utf8(std::string_view text);

}  // namespace azt
