#include "config/time_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {

TimeConfig time_config_from(const ConfigFile& file) {
  const ConfigSection s = file.section("time");
  TimeConfig c;
  c.chronyc = s.text("chronyc").value_or(c.chronyc);
  if (c.chronyc.empty()) s.fail("chronyc", "must name the chronyc program");
  c.chrony_socket = s.text("chrony_socket").value_or("");
  c.poll_s = s.number("poll_s").value_or(c.poll_s);
  c.rtc = s.text("rtc").value_or(c.rtc);
  c.manage_chrony = s.boolean("manage_chrony").value_or(false);
  c.sources_file = s.text("sources_file").value_or(c.sources_file);
  if (c.sources_file.empty() || c.sources_file.front() != '/' || c.sources_file.size() < 9 ||
      c.sources_file.substr(c.sources_file.size() - 8) != ".sources") {
    s.fail("sources_file",
           "must be an absolute path ending in .sources (chrony's sourcedir reads "
           "only those)");
  }
  return c;
}

}  // namespace azt::app
