#include "config/export_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {

ExportConfig export_config_from(const ConfigFile& file) {
  const ConfigSection s = file.section("export");
  ExportConfig c;
  c.azel_dat = s.text("azel_dat").value_or("");
  if (!c.azel_dat.empty() && (c.azel_dat.front() != '/' || c.azel_dat.back() == '/')) {
    s.fail("azel_dat",
           "must be an absolute file path (WSJT-X's is in its data folder, e.g. "
           "\"/home/op/.local/share/WSJT-X/azel.dat\")");
  }
  c.azel_dat_pol_line = s.boolean("azel_dat_pol_line").value_or(false);
  return c;
}

}  // namespace azt::app
