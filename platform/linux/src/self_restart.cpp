#include "azt/linux/self_restart.hpp"

#include <linux/close_range.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace azt::linux_os {
namespace {

/// The arguments as the kernel kept them: NUL-separated in /proc/self/cmdline.
std::vector<std::string> own_arguments() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  std::string::size_type start = 0;
  while (start < text.size()) {
    const auto end = text.find('\0', start);
    args.push_back(text.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return args;
}

}  // namespace

bool started_by_systemd() {
  const char* id = std::getenv("INVOCATION_ID");
  return id != nullptr && *id != '\0';
}

Result<bool> reexec_self() {
  std::vector<std::string> args = own_arguments();
  if (args.empty()) return fail("cannot read /proc/self/cmdline");
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // Listening sockets, lock files and devices must not outlive the exec: the new process opens
  // its own. close_range marks them all at once (Linux 5.11); an older kernel keeps CLOEXEC as
  // each was opened with.
  (void)syscall(SYS_close_range, 3U, ~0U, CLOSE_RANGE_CLOEXEC);
  execv("/proc/self/exe", argv.data());
  return fail(std::string("exec /proc/self/exe: ") + std::strerror(errno));
}

}  // namespace azt::linux_os
