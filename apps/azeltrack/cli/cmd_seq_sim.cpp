// `azeltrack seq-sim`: the T/R sequencer of the configuration run in virtual time, so its timing
// can be checked from outside (docs/hardware.md). Prints every output transition.
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "azt/sequencer/tr_sequencer.hpp"
#include "azt/util/parse_number.hpp"
#include "cli/commands.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {
namespace {

struct SeqSimOptions {
  std::string config;
  std::string ptt;
  double until_ms = -1.0;
  bool json = false;
};

/// "0:down,500:up,…" (down = PTT pressed, as on an active-low line) -> edges in time order.
std::vector<std::pair<double, bool>> parse_ptt(const std::string& text) {
  std::vector<std::pair<double, bool>> edges;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos)
      throw UsageError("--ptt: '" + item + "' is not TIME_MS:down|up");
    const auto t = parse_finite_double(std::string_view(item).substr(0, colon));
    const std::string level = item.substr(colon + 1);
    if (!t || *t < 0.0) throw UsageError("--ptt: '" + item + "': the time must be ms ≥ 0");
    if (level != "down" && level != "up") throw UsageError("--ptt: '" + item + "': down or up");
    if (!edges.empty() && *t < edges.back().first)
      throw UsageError("--ptt: times must not go back");
    edges.emplace_back(*t, level == "down");
  }
  if (edges.empty()) throw UsageError("--ptt: give at least one TIME_MS:down|up");
  return edges;
}

int run(const SeqSimOptions& o) {
  const DaemonConfig config = daemon_config_from(ConfigFile::load(o.config));
  const auto edges = parse_ptt(o.ptt);
  const double until = o.until_ms >= 0.0 ? o.until_ms : edges.back().first + 1000.0;
  sequencer::TrSequencer seq(config.sequencer);
  std::size_t next = 0;
  bool level = false;
  for (;;) {
    const double edge_t = next < edges.size() ? edges[next].first : until + 1.0;
    const double t = std::min(edge_t, seq.next_deadline_ms().value_or(until + 1.0));
    if (t > until) break;
    while (next < edges.size() && edges[next].first <= t) level = edges[next++].second;
    for (const auto& tr : seq.update(t, level)) {
      const std::string& line = config.sequencer.outputs[tr.line];
      if (o.json) {
        std::cout << nlohmann::json{{"t_ms", tr.t_ms},
                                    {"line", line},
                                    {"state", tr.on ? "on" : "off"}}
                         .dump()
                  << '\n';
      } else {
        std::cout << std::fixed << std::setprecision(3) << std::setw(12) << tr.t_ms << " ms  "
                  << std::left << std::setw(12) << line << std::right << (tr.on ? "on" : "off")
                  << '\n';
      }
    }
  }
  return 0;
}

}  // namespace

Runner add_seq_sim_command(CLI::App& app) {
  auto o = std::make_shared<SeqSimOptions>();
  CLI::App* cmd = app.add_subcommand(
      "seq-sim", "Run the configuration's T/R sequencer in virtual time and print its transitions");
  cmd->add_option("--config", o->config, "Configuration file ([sequencer])")->required();
  cmd->add_option("--ptt", o->ptt, "PTT edges: TIME_MS:down|up,… (down = pressed)")->required();
  cmd->add_option("--until", o->until_ms, "Stop at this time (default: last edge + 1000 ms)");
  cmd->add_flag("--json", o->json, "One JSON object per transition: t_ms, line, state");
  return [o] { return run(*o); };
}

}  // namespace azt::app
