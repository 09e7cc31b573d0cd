#pragma once
// The outer shape of a Debian binary package, checked before an upload is handed to the root
// update helper (docs/packaging.md): a .deb is an ar(5) archive whose members are, in this order,
// `debian-binary` ("2.0\n"), `control.tar[.gz|.xz|.zst]` and `data.tar[.gz|.xz|.zst|.bz2]`
// (deb(5)). This check reads only the ar headers, so the operator learns at once that a file is
// not a package at all; the helper's dpkg-deb checks the rest (the control fields, every byte of
// the compressed members) before anything is installed.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::software {

struct DebArchive {
  std::string format_version;    ///< debian-binary's first line: "2.0"
  std::string control_member;    ///< "control.tar.xz"
  std::string data_member;       ///< "data.tar.xz"
  std::uint64_t data_bytes = 0;  ///< the compressed data member's size
};

/// Up to `n` bytes of the archive from `offset` (fewer at its end): how the check reads a package
/// it does not hold (an upload streamed to a file). It reads the headers and the
/// few bytes of debian-binary only.
using ReadAt = std::function<std::string(std::uint64_t offset, std::size_t n)>;

/// The archive of `size` bytes, its members as deb(5) requires them; an Error names the first
/// thing wrong.
Result<DebArchive> check_deb_archive(std::uint64_t size, const ReadAt& read_at);
/// The same for an archive in memory.
Result<DebArchive> check_deb_archive(std::string_view bytes);

}  // namespace azt::software
