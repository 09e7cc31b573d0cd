#include "azt/software/deb_archive.hpp"

#include <algorithm>
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
  std::uint64_t start = 0;  ///< where its body begins
  std::uint64_t size = 0;
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
Result<Member> read_member(std::uint64_t archive_size, const ReadAt& read_at,
                           std::uint64_t& offset) {
  // After an odd-sized last member the padding byte may be missing: offset is then past the end.
  if (offset > archive_size || archive_size - offset < kHeaderBytes) {
    return fail("a member's header is cut short");
  }
  const std::string header = read_at(offset, kHeaderBytes);
  if (header.size() != kHeaderBytes) return fail("a member's header is cut short");
  if (header.substr(58, 2) != "`\n") return fail("a member's header is malformed");
  const auto size = decimal(std::string_view(header).substr(48, 10));
  if (!size) return fail("a member's size is not a decimal number");
  const std::uint64_t start = offset + kHeaderBytes;
  if (*size > archive_size - start) return fail("a member runs past the end of the file");
  offset = start + *size + (*size % 2);  // bodies are padded to an even length
  return Member{member_name(std::string_view(header).substr(0, 16)), start, *size};
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

Result<std::string> format_version(const Member& m, const ReadAt& read_at) {
  if (m.name != "debian-binary") return fail("the first member is not debian-binary");
  // "2.0\n" in every package; a longer line is read only as far as a version could go.
  const std::string body =
      read_at(m.start, static_cast<std::size_t>(std::min<std::uint64_t>(m.size, 64)));
  const auto line_end = body.find('\n');
  if (line_end == std::string::npos) return fail("debian-binary has no version line");
  const std::string_view version = std::string_view(body).substr(0, line_end);
  // deb(5): a major version other than 2 is a different format altogether.
  if (version.substr(0, 2) != "2.") return fail("format version is not 2.x");
  return std::string(version);
}

}  // namespace

Result<DebArchive> check_deb_archive(std::uint64_t size, const ReadAt& read_at) {
  if (read_at(0, kArMagic.size()) != kArMagic) {
    return fail("not a Debian package (no ar archive header)");
  }
  std::uint64_t offset = kArMagic.size();
  std::array<Member, 3> members;
  for (auto& m : members) {
    auto member = read_member(size, read_at, offset);
    if (!member) return fail("not a Debian package: " + member.error().message);
    m = std::move(member).value();
  }
  auto version = format_version(members[0], read_at);
  if (!version) return fail("not a Debian package: " + version.error().message);
  if (!one_of(members[1].name, "control.tar", {"", ".gz", ".xz", ".zst"})) {
    return fail("not a Debian package: the second member is not control.tar");
  }
  if (!one_of(members[2].name, "data.tar", {"", ".gz", ".xz", ".zst", ".bz2", ".lzma"})) {
    return fail("not a Debian package: the third member is not data.tar");
  }
  return DebArchive{std::move(version).value(), members[1].name, members[2].name, members[2].size};
}

Result<DebArchive> check_deb_archive(std::string_view bytes) {
  return check_deb_archive(bytes.size(), [bytes](std::uint64_t offset, std::size_t n) {
    return offset >= bytes.size() ? std::string() : std::string(bytes.substr(offset, n));
  });
}

}  // namespace azt::software
