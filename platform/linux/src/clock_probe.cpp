#include "azt/linux/clock_probe.hpp"

#include <utility>
#include <vector>

#include "azt/linux/command_output.hpp"
#include "azt/linux/kernel_clock.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::linux_os {
namespace {

std::vector<std::string> chronyc_argv(const ClockProbeConfig& config,
                                      std::vector<std::string> command) {
  std::vector<std::string> argv{config.chronyc};
  if (!config.chrony_host.empty()) argv.insert(argv.end(), {"-h", config.chrony_host});
  argv.insert(argv.end(), command.begin(), command.end());
  return argv;
}

/// chronyc's complaint: its standard error's first line, or what it printed instead.
std::string complaint(const CommandOutput& out) {
  const auto lines = split_lines(out.err.empty() ? out.out : out.err);
  const std::string first = lines.empty() ? "" : std::string(trim(lines.front()));
  return first.empty() ? "chronyc exited with status " + std::to_string(out.exit_code) : first;
}

/// `chronyc -c -n -m tracking sources`: one tracking line, then one line per source.
void read_chrony(const ClockProbeConfig& config, timekeeping::ClockReading& reading) {
  const auto run = run_command(chronyc_argv(config, {"-c", "-n", "-m", "tracking", "sources"}),
                               {config.timeout_s});
  if (!run) {
    reading.chrony_error = run.error().message;
    return;
  }
  if (run.value().exit_code != 0) {
    reading.chrony_error = complaint(run.value());
    return;
  }
  const std::string& text = run.value().out;
  const auto newline = text.find('\n');
  auto tracking = timekeeping::parse_chrony_tracking(text.substr(0, newline));
  if (!tracking) {
    reading.chrony_error = tracking.error().message;
    return;
  }
  reading.tracking = std::move(tracking).value();
  auto sources = timekeeping::parse_chrony_sources(
      newline == std::string::npos ? "" : std::string_view(text).substr(newline + 1));
  if (sources)
    reading.sources = std::move(sources).value();
  else
    reading.chrony_error = sources.error().message;
}

}  // namespace

timekeeping::ClockReading probe_clock(const ClockProbeConfig& config) {
  timekeeping::ClockReading reading;
  read_chrony(config, reading);
  if (const auto kernel = read_kernel_clock()) reading.kernel_synced = kernel.value().synchronised;
  reading.rtc_present = rtc_present(config.rtc_device);
  return reading;
}

Result<bool> reload_chrony_sources(const ClockProbeConfig& config) {
  const auto run = run_command(chronyc_argv(config, {"reload", "sources"}), {config.timeout_s});
  if (!run) return run.error();
  if (run.value().exit_code != 0) return fail("chronyc reload sources: " + complaint(run.value()));
  return true;
}

}  // namespace azt::linux_os
