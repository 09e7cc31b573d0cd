#include "azt/util/valid_utf8.hpp"

#include <cstddef>

namespace azt {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

/// The second byte's allowed range after a lead byte (table 3-7); later bytes are 80..BF.
struct LeadRule {
  std::size_t length = 0;  ///< 0: not a lead byte
  unsigned char second_min = 0x80;
  unsigned char second_max = 0xBF;
};

LeadRule rule_for(unsigned char lead) {
  if (lead < 0x80) return {1};
  if (lead >= 0xC2 && lead <= 0xDF) return {2};
  if (lead == 0xE0) return {3, 0xA0, 0xBF};  // no overlongs
  if (lead == 0xED) return {3, 0x80, 0x9F};  // no surrogates
  if (lead >= 0xE1 && lead <= 0xEF) return {3};
  if (lead == 0xF0) return {4, 0x90, 0xBF};  // no overlongs
  if (lead == 0xF4) return {4, 0x80, 0x8F};  // nothing above U+10FFFF
  if (lead >= 0xF1 && lead <= 0xF3) return {4};
  return {};
}

/// How many bytes from `at` form one well-formed character (the `ok` case) or, if ill-formed,
/// the maximal subpart to replace by one U+FFFD.
std::size_t next_sequence(std::string_view text, std::size_t at, bool& ok) {
  const auto lead = static_cast<unsigned char>(text[at]);
  const LeadRule rule = rule_for(lead);
  ok = false;
  if (rule.length == 0) return 1;
  for (std::size_t i = 1; i < rule.length; ++i) {
    if (at + i >= text.size()) return i;
    const auto c = static_cast<unsigned char>(text[at + i]);
    const unsigned char lo = i == 1 ? rule.second_min : 0x80;
    const unsigned char hi = i == 1 ? rule.second_max : 0xBF;
    if (c < lo || c > hi) return i;
  }
  ok = true;
  return rule.length;
}

}  // namespace

bool is_valid_utf8(std::string_view text) {
  for (std::size_t at = 0; at < text.size();) {
    bool ok = false;
    at += next_sequence(text, at, ok);
    if (!ok) return false;
  }
  return true;
}

std::string valid_utf8(std::string_view text) {
  if (is_valid_utf8(text)) return std::string(text);
  std::string out;
  out.reserve(text.size() + 8);
  for (std::size_t at = 0; at < text.size();) {
    bool ok = false;
    const std::size_t n = next_sequence(text, at, ok);
    if (ok) {
      out.append(text.substr(at, n));
    } else {
      out.append(kReplacement);
    }
    at += n;
  }
  return out;
}

}  // namespace azt
