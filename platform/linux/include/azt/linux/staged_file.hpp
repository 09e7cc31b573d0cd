#pragma once
// A file written in pieces and published whole at a path, or not at all: an upload streamed to
// disk as it arrives, never held whole in memory. Until publish() it is an
// unnamed file in the target's folder (open(2)'s O_TMPFILE), so an abandoned upload, a kill or a
// power cut leaves nothing behind, and nobody can open it by a name meanwhile. publish() makes it
// durable and gives it its name in one rename(2): readers see the old file or the whole new one.

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "azt/linux/unique_fd.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

class StagedFile {
 public:
  /// An empty unnamed file in `dir` (which must exist) that will have `mode` when published.
  static Result<StagedFile> create(const std::string& dir, mode_t mode);

  Result<bool> append(std::string_view bytes);
  [[nodiscard]] std::uint64_t size() const { return size_; }
  /// Up to `n` bytes from `offset`: fewer at the end, none on a read error.
  [[nodiscard]] std::string read_at(std::uint64_t offset, std::size_t n) const;
  /// fsyncs it, renames it over `path` (in the folder it was created in) and fsyncs the folder.
  Result<bool> publish(const std::string& path);

 private:
  StagedFile(UniqueFd fd, std::string dir, mode_t mode)
      : fd_(std::move(fd)), dir_(std::move(dir)), mode_(mode) {}

  UniqueFd fd_;
  std::string dir_;
  mode_t mode_;
  std::uint64_t size_ = 0;
};

}  // namespace azt::linux_os
