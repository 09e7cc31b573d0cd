#include "azt/linux/staged_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

#include "file_steps.hpp"

namespace azt::linux_os {

Result<StagedFile> StagedFile::create(const std::string& dir, mode_t mode) {
  // 0600 while it is written; `mode` only once it is whole (publish).
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0) return step_error("create an unnamed file in", dir, errno);
  return StagedFile(UniqueFd(fd), dir, mode);
}

Result<bool> StagedFile::append(std::string_view bytes) {
  if (const int err = write_all(fd_.get(), bytes); err != 0) {
    return step_error("write the file being received in", dir_, err);
  }
  size_ += bytes.size();
  return true;
}

std::string StagedFile::read_at(std::uint64_t offset, std::size_t n) const {
  std::string bytes(n, '\0');
  std::size_t got = 0;
  while (got < n) {
    const ssize_t r =
        ::pread(fd_.get(), bytes.data() + got, n - got, static_cast<off_t>(offset + got));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) return {};
    if (r == 0) break;
    got += static_cast<std::size_t>(r);
  }
  bytes.resize(got);
  return bytes;
}

Result<bool> StagedFile::publish(const std::string& path) {
  if (const int err = fsync_retrying(fd_.get()); err != 0) {
    return step_error("fsync the file received in", dir_, err);
  }
  if (::fchmod(fd_.get(), mode_) != 0) return step_error("set the mode of", path, errno);
  // An unnamed file gets a name through its /proc link (linkat(2)'s AT_EMPTY_PATH would need
  // CAP_DAC_READ_SEARCH); a temp name first, because linkat never replaces what is there.
  const std::string temp = path + ".tmp." + std::to_string(::getpid());
  ::unlink(temp.c_str());
  const std::string self = "/proc/self/fd/" + std::to_string(fd_.get());
  if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, temp.c_str(), AT_SYMLINK_FOLLOW) != 0) {
    return step_error("give a name to the file received as", temp, errno);
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    return step_error("rename the file received over", path, err);
  }
  return fsync_directory_of(path);
}

}  // namespace azt::linux_os
