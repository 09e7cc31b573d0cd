#include "azt/software/deb_archive.hpp"

#include <array>
#include <charconv>
#include <initializer_list>
#include <optional>

namespace azt::software {
namespace {

constexpr std::string_view kArMagic = "!<arch>\n";
constexpr std::size_t kHeaderBytes = 60;  // ar(5): name 16, mtime 12, uid 6, gid 6, mode 8,
                                          // size 10, terminator "`\n"

struct Member {
  std::string name;
  std::string_view body;
};

std::string_view trim_right(std::string_view s) {
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

/// The member name without ar's padding, or GNU ar's '/' terminator.
std::string member_name(std::string_view field) {
  field = trim_right(field);
  if (!field.empty() && field.back() == '/') field.remove_suffix(1);
  return std::string(field);
}

std::optional<std::uint64_t> decimal(std::string_view field) {
  field = trim_right(field);
  std::uint64_t value = 0;
  const auto* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if (field.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

/// The member starting at `offset` (its header), advancing `offset` past its padded body.
Result<Member> read_member(std::string_view bytes, std::size_t& offset) {
  // After an odd-sized last member the padding byte may be missing: offset is then past the end.
  if (offset > bytes.size() || bytes.size() - offset < kHeaderBytes) {
    return fail("a member's header is cut short");
  }
  const std::string_view header = bytes.substr(offset, kHeaderBytes);
  if (header.substr(58, 2) != "`\n") return fail("a member's header is malformed");
  const auto size = decimal(header.substr(48, 10));
  if (!size) return fail("a member's size is not a decimal number");
  const std::size_t start = offset + kHeaderBytes;
  if (*size > bytes.size() - start) return fail("a member runs past the end of the file");
  offset = start + *size + (*size % 2);  // bodies are padded to an even length
  return Member{member_name(header.substr(0, 16)), bytes.substr(start, *size)};
}

bool one_of(std::string_view name, std::string_view stem,
            std::initializer_list<std::string_view> suffixes) {
  if (name.substr(0, stem.size()) != stem) return false;
  const std::string_view rest = name.substr(stem.size());
  for (const auto s : suffixes) {
    if (rest == s) return true;
  }
  return false;
}

Result<std::string> format_version(const Member& m) {
  if (m.name != "debian-binary") return fail("the first member is not debian-binary");
  const auto line_end = m.body.find('\n');
  if (line_end == std::string_view::npos) return fail("debian-binary has no version line");
  const std::string_view version = m.body.substr(0, line_end);
  // deb(5): a major version other than 2 is a different format altogether.
  if (version.substr(0, 2) != "2.") return fail("format version is not 2.x");
  return std::string(version);
}

}  // namespace

Result<DebArchive> check_deb_archive(std::string_view bytes) {
  if (bytes.substr(0, kArMagic.size()) != kArMagic) {
    return fail("not a Debian package (no ar archive header)");
  }
  std::size_t offset = kArMagic.size();
  std::array<Member, 3> members;
  for (auto& m : members) {
    auto member = read_member(bytes, offset);
    if (!member) return fail("not a Debian package: " + member.error().message);
    m = std::move(member).value();
  }
  auto version = format_version(members[0]);
  if (!version) return fail("not a Debian package: " + version.error().message);
  if (!one_of(members[1].name, "control.tar", {"", ".gz", ".xz", ".zst"})) {
    return fail("not a Debian package: the second member is not control.tar");
  }
  if (!one_of(members[2].name, "data.tar", {"", ".gz", ".xz", ".zst", ".bz2", ".lzma"})) {
    return fail("not a Debian package: the third member is not data.tar");
  }
  return DebArchive{std::move(version).value(), members[1].name, members[2].name,
                    members[2].body.size()};
}

}  // namespace azt::software
