#include "azt/linux/runtime_dir.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace azt::linux_os {

std::string runtime_dir() {
  // systemd's RuntimeDirectory= (the unit's /run/azeltrack, owned by its User=) comes first.
  if (const char* unit = std::getenv("RUNTIME_DIRECTORY"); unit != nullptr && unit[0] == '/') {
    const std::string dir(unit);
    return dir.substr(0, dir.find(':'));  // several directories are ':'-separated
  }
  if (::geteuid() == 0) return "/run/azeltrack";
  if (const char* xdg = std::getenv("XDG_RUNTIME_DIR"); xdg != nullptr && xdg[0] == '/') {
    return std::string(xdg) + "/azeltrack";
  }
  return "/tmp/azeltrack-" + std::to_string(::geteuid());
}

Result<bool> ensure_private_dir(const std::string& dir) {
  struct stat st {};
  if (::lstat(dir.c_str(), &st) != 0) {
    if (errno != ENOENT) return fail(dir + ": " + std::strerror(errno));
    const std::filesystem::path path(dir);
    if (path.has_parent_path() && path.parent_path() != path) {
      std::error_code ec;
      std::filesystem::create_directories(path.parent_path(), ec);
      if (ec) return fail("cannot create " + path.parent_path().string() + ": " + ec.message());
    }
    // 0700 from the start (mkdir applies the umask, which can only take bits away).
    if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) {
      return fail("cannot create " + dir + ": " + std::strerror(errno));
    }
    if (::lstat(dir.c_str(), &st) != 0) return fail(dir + ": " + std::strerror(errno));
  }
  if (S_ISLNK(st.st_mode)) return fail(dir + " is a symbolic link: refused (use a directory)");
  if (!S_ISDIR(st.st_mode)) return fail(dir + " exists and is not a directory");
  if (st.st_uid != ::geteuid()) {
    return fail(dir + " belongs to user " + std::to_string(st.st_uid) +
                ", not to this program's user " + std::to_string(::geteuid()) +
                ": refused (another user could replace the links in it)");
  }
  return true;
}

}  // namespace azt::linux_os
