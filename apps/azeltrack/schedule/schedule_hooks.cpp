#include "schedule/schedule_hooks.hpp"

#include <spdlog/spdlog.h>

#include <cstdlib>
#include <system_error>

#include "azt/astro/time_scales.hpp"
#include "azt/util/format_number.hpp"
#include "azt/util/valid_utf8.hpp"
#include "schedule/hook_report.hpp"

namespace azt::app {
namespace {

std::string from_environment(const char* name) {
  const char* value = std::getenv(name);  // NOLINT(concurrency-mt-unsafe): read once, at start
  return value != nullptr ? value : "";
}

void journal(const std::string& line, bool ok) {
  if (ok) {
    spdlog::info("{}", line);
  } else {
    spdlog::warn("{}", line);
  }
}

/// "hook aos ISS (25544): /usr/local/bin/aos", as the journal and the events name it.
std::string who_of(HookEvent event, const HookPass& pass, const std::string& program) {
  std::string who = "hook " + std::string(hook_event_name(event));
  if (!pass.sat.empty())
    who += " " + pass.sat + (pass.norad.empty() ? "" : " (" + pass.norad + ")");
  return valid_utf8(who + ": " + program);
}

}  // namespace

std::string_view hook_event_name(HookEvent event) {
  switch (event) {
    case HookEvent::Aos:
      return "aos";
    case HookEvent::Los:
      return "los";
    case HookEvent::PrePosition:
      return "pre_position";
    case HookEvent::Park:
      return "park";
  }
  return "?";
}

std::vector<std::string> hook_environment(HookEvent event, const HookPass& pass,
                                          const HookHome& home) {
  const bool has_pass = !pass.sat.empty();
  const auto when = [has_pass](double unix_s) {
    return has_pass ? astro::format_iso8601_utc_unix(unix_s) : std::string();
  };
  std::vector<std::string> env{
      "AZT_EVENT=" + std::string(hook_event_name(event)),
      "AZT_SAT=" + pass.sat,
      "AZT_NORAD=" + (has_pass ? pass.norad : std::string()),
      "AZT_AOS=" + when(pass.aos_unix_s),
      "AZT_LOS=" + when(pass.los_unix_s),
      "AZT_MAX_EL=" + (has_pass ? format_fixed(pass.max_el_deg, 1) : std::string()),
      "PATH=/usr/local/bin:/usr/bin:/bin"};
  if (!home.home.empty()) env.push_back("HOME=" + home.home);
  if (!home.lang.empty()) env.push_back("LANG=" + home.lang);
  return env;
}

ScheduleHooks::ScheduleHooks(boost::asio::io_context& io, HooksConfig config, Report report)
    : io_(io),
      config_(std::move(config)),
      report_(std::move(report)),
      home_{from_environment("HOME"), from_environment("LANG")} {}

ScheduleHooks::~ScheduleHooks() {
  alive_.reset();
  for (const auto& run : runs_) run->stop.stop();
  for (const auto& run : runs_) {
    if (run->thread.joinable()) run->thread.join();
    journal(run->who + ": " + hook_ending(run->result, config_.timeout_s),
            hook_succeeded(run->result));
  }
}

void ScheduleHooks::fire(HookEvent event, const HookPass& pass) {
  const auto& argv = program_of(event);
  if (argv.empty()) return;
  auto run = std::make_unique<Run>();
  run->who = who_of(event, pass, argv.front());
  if (runs_.size() >= kMaxRunning) {
    const std::string line =
        run->who + ": not run: " + std::to_string(kMaxRunning) + " hooks are still running";
    journal(line, false);
    if (report_) report_(line);
    return;
  }
  linux_os::ChildSpec spec{
      .argv = argv, .env = hook_environment(event, pass, home_), .timeout_s = config_.timeout_s};
  runs_.push_back(std::move(run));
  start(*runs_.back(), std::move(spec));
}

const std::vector<std::string>& ScheduleHooks::program_of(HookEvent event) const {
  switch (event) {
    case HookEvent::Aos:
      return config_.aos;
    case HookEvent::Los:
      return config_.los;
    case HookEvent::PrePosition:
      return config_.pre_position;
    case HookEvent::Park:
      return config_.park;
  }
  return config_.aos;
}

void ScheduleHooks::start(Run& run, linux_os::ChildSpec spec) {
  Run* r = &run;
  try {
    r->thread = std::thread([this, r, spec = std::move(spec), alive = std::weak_ptr(alive_)] {
      r->result = linux_os::run_child(spec, &r->stop);
      // The owner joins this thread before it goes, so io_ is still there to post to.
      boost::asio::post(io_, [this, r, alive] {
        if (alive.lock()) finished(r);
      });
    });
  } catch (const std::system_error& e) {
    r->result.spawn_error = std::string("no thread to run it on: ") + e.what();
    boost::asio::post(io_, [this, r, alive = std::weak_ptr(alive_)] {
      if (alive.lock()) finished(r);
    });
  }
}

void ScheduleHooks::finished(Run* run) {
  if (run->thread.joinable()) run->thread.join();  // it has only its return left
  const bool ok = hook_succeeded(run->result);
  const std::string line = run->who + ": " + hook_ending(run->result, config_.timeout_s);
  const std::string output = hook_output(run->result, kJournalBytes);
  const std::string console = hook_output(run->result, kReportBytes);
  journal(line + (output.empty() ? "" : ": " + output), ok);
  if (report_) report_(line + (console.empty() ? "" : ": " + console));
  runs_.remove_if([run](const std::unique_ptr<Run>& r) { return r.get() == run; });
}

}  // namespace azt::app
