#include "config/hooks_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {
namespace {

std::vector<std::string> read_hook(const ConfigSection& s, std::string_view key) {
  auto argv = s.text_list(key).value_or(std::vector<std::string>{});
  if (argv.empty()) return argv;
  // No PATH search: the daemon's PATH is not the operator's shell's, and a relative name would
  // run whatever the daemon's working folder holds.
  if (argv.front().empty() || argv.front().front() != '/') {
    s.fail(key, "must name the program by its absolute path (\"/usr/local/bin/...\")");
  }
  for (const auto& arg : argv) {
    if (arg.find('\0') != std::string::npos) s.fail(key, "must not hold a NUL character");
  }
  return argv;
}

}  // namespace

HooksConfig hooks_config_from(const ConfigFile& file) {
  const ConfigSection s = file.section("hooks");
  HooksConfig c;
  c.aos = read_hook(s, "aos");
  c.los = read_hook(s, "los");
  c.pre_position = read_hook(s, "pre_position");
  c.park = read_hook(s, "park");
  c.timeout_s = s.number("timeout_s").value_or(c.timeout_s);
  return c;
}

}  // namespace azt::app
