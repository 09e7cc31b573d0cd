// libFuzzer target for the configuration loader (docs/reliability.md R23, R24).
//
// Input: the bytes of a configuration file. Invariants:
// - parsing and validating (ConfigFile::parse, migrations, daemon_config_from) either accept the
//   file or throw UsageError, the one error the program reports as "bad configuration"; any other
//   exception, crash or sanitizer report is a finding;
// - save -> load is the identity for an accepted file: what ConfigStore writes parses and
//   validates again, and writing that gives the same bytes;
// - a comment-keeping edit (config_text_edit.hpp) of an accepted file, when it applies, gives a
//   text that parses to exactly the edited table.
#include <spdlog/spdlog.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/config_store.hpp"
#include "config/config_text_edit.hpp"
#include "config/daemon_config.hpp"
#include "fuzz_support.hpp"

namespace {

namespace app = azt::app;

/// A saved file must load: any error here is a finding, not a rejection.
std::string save_and_reload(const std::string& saved) {
  try {
    const app::ConfigFile again = app::ConfigFile::parse(saved, "saved.toml");
    (void)app::daemon_config_from(again);
    AZT_FUZZ_REQUIRE(again.migration().changes.empty());  // a saved file is current
    return app::ConfigStore::serialize(again.root());
  } catch (const app::UsageError& e) {
    std::fprintf(stderr, "saved file does not load: %s\n%s\n", e.what(), saved.c_str());
    AZT_FUZZ_REQUIRE(false);
  }
  return {};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  spdlog::set_level(spdlog::level::off);  // DUT1 and leap-second warnings are not findings
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string saved;
  try {
    const app::ConfigFile file = app::ConfigFile::parse(text, "fuzz.toml");
    (void)app::daemon_config_from(file);
    saved = app::ConfigStore::serialize(file.root());
  } catch (const app::UsageError&) {
    return 0;  // refused with a message: the expected outcome for most inputs
  }
  AZT_FUZZ_REQUIRE(save_and_reload(saved) == saved);
  // The console's typical edits: a changed value, a new key, a new table.
  const toml::table before = toml::parse(text);
  toml::table after = before;
  if (!after.contains("control")) after.insert("control", toml::table{});
  if (toml::table* control = after["control"].as_table()) {
    control->insert_or_assign("window_deg", 0.5);
  }
  after.insert_or_assign("web", toml::table{{"port", 8090}});
  if (const auto edited = app::edit_toml_text(std::string(text), before, after)) {
    AZT_FUZZ_REQUIRE(toml::parse(*edited) == after);
  }
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) { return azt::fuzz::replay_files("config_fuzz", argc, argv); }
#endif
