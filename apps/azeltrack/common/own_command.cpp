#include "common/own_command.hpp"

#include <filesystem>
#include <system_error>

namespace azt::app {

std::string own_command() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec || exe.empty() ? std::string("azeltrack") : exe.string();
}

std::string password_command(const std::string& config_path) {
  std::error_code ec;
  const std::filesystem::path config = std::filesystem::absolute(config_path, ec);
  return own_command() + " web password --config " + (ec ? config_path : config.string());
}

}  // namespace azt::app
