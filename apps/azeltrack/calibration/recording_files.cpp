#include "calibration/recording_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "calibration/recorder.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;

std::string errno_text(const std::string& step) { return step + ": " + std::strerror(errno); }

/// Lines after the header: the rows.
std::size_t count_rows(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::size_t lines = 0;
  std::string line;
  while (std::getline(in, line)) ++lines;
  return lines > 0 ? lines - 1 : 0;
}

}  // namespace

Result<bool> append_recording(const std::string& dir, const std::string& name,
                              const std::string& text, bool first) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return fail("cannot make " + dir + ": " + ec.message());
  const std::string path = (fs::path(dir) / name).string();
  const int flags = O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC | (first ? O_EXCL : 0);
  const int fd = ::open(path.c_str(), flags, 0644);
  if (fd < 0) return fail(errno_text("open " + path));
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const auto failed = fail(errno_text("write " + path));
      ::close(fd);
      return failed;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) return fail(errno_text("close " + path));
  return true;
}

nlohmann::json list_recordings(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file(ec) && is_recording_file_name(name)) names.push_back(name);
  }
  // The names hold the UTC start: sorting them sorts by time.
  std::sort(names.rbegin(), names.rend());
  nlohmann::json list = nlohmann::json::array();
  for (const auto& name : names) {
    const fs::path path = fs::path(dir) / name;
    const auto bytes = fs::file_size(path, ec);
    list.push_back({{"name", name}, {"bytes", ec ? 0 : bytes}, {"rows", count_rows(path)}});
  }
  return {{"recordings", list}};
}

Result<std::string> read_recording(const std::string& dir, const std::string& name) {
  if (!is_recording_file_name(name)) return fail("no such recording: " + name);
  std::ifstream in(fs::path(dir) / name, std::ios::binary);
  if (!in) return fail("no such recording: " + name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace azt::app
