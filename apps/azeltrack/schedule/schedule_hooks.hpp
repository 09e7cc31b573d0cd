#pragma once
// The schedule's hooks (docs/satellites.md "Hooks"): the operator's programs run at a scheduled
// pass's AOS and LOS, when the antenna pre-positions for one and when it parks, with the pass in
// their environment. Each runs on a thread of its own (linux_os::run_child: no shell, its own
// process group, a timeout), never on the event loop, and at most kMaxRunning at once: one more
// is refused and said, never queued, so a hook that hangs or floods its output delays neither the
// loop nor another hook, and changes nothing in tracking. How each ended, with its first lines of
// output, goes to the journal and to `report` (the console's recent events), on the loop.

#include <cstddef>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "azt/linux/asio.hpp"
#include "azt/linux/child_process.hpp"
#include "config/hooks_config.hpp"

namespace azt::app {

enum class HookEvent { Aos, Los, PrePosition, Park };

/// "aos", "los", "pre_position", "park": the [hooks] key and AZT_EVENT's value.
std::string_view hook_event_name(HookEvent event);

/// The pass a hook is about; `sat` empty: none (a park with no pass planned), and the pass's
/// variables are then empty.
struct HookPass {
  std::string sat;    ///< the satellite's name
  std::string norad;  ///< its catalogue number, as text
  double aos_unix_s = 0.0;
  double los_unix_s = 0.0;
  double max_el_deg = 0.0;
};

/// What the hook's environment takes from the daemon's own (unset: left out).
struct HookHome {
  std::string home;  ///< HOME
  std::string lang;  ///< LANG
};

/// The hook's whole environment: AZT_EVENT, AZT_SAT, AZT_NORAD, AZT_AOS and AZT_LOS (ISO 8601
/// UTC), AZT_MAX_EL (degrees), PATH=/usr/local/bin:/usr/bin:/bin, and HOME and LANG when known.
std::vector<std::string> hook_environment(HookEvent event, const HookPass& pass,
                                          const HookHome& home);

class ScheduleHooks {
 public:
  using Report = std::function<void(const std::string&)>;
  static constexpr std::size_t kMaxRunning = 4;
  /// The journal keeps this much of a hook's output, the console's events less.
  static constexpr std::size_t kJournalBytes = 2048;
  static constexpr std::size_t kReportBytes = 300;

  /// `report` runs on `io`'s loop. HOME and LANG are read from this process's environment now.
  ScheduleHooks(boost::asio::io_context& io, HooksConfig config, Report report);
  /// Running hooks are killed at once (SIGKILL to their groups) and their threads joined: a
  /// shutdown never waits for a hook's timeout. Their endings go to the journal only.
  ~ScheduleHooks();
  ScheduleHooks(const ScheduleHooks&) = delete;
  ScheduleHooks& operator=(const ScheduleHooks&) = delete;

  /// Starts the hook of `event`, if one is configured; returns at once. Called on the loop.
  void fire(HookEvent event, const HookPass& pass);
  /// Hooks started whose ending has not been reported yet.
  [[nodiscard]] std::size_t running() const { return runs_.size(); }

 private:
  struct Run {
    std::string who;  ///< "hook aos ISS (25544): /usr/local/bin/aos"
    linux_os::ChildStop stop;
    linux_os::ChildResult result;
    std::thread thread;
  };

  [[nodiscard]] const std::vector<std::string>& program_of(HookEvent event) const;
  void start(Run& run, linux_os::ChildSpec spec);
  void finished(Run* run);

  boost::asio::io_context& io_;
  HooksConfig config_;
  Report report_;
  HookHome home_;
  std::list<std::unique_ptr<Run>> runs_;
  /// Expires first in the destructor: an ending posted by a hook's thread then finds no owner.
  std::shared_ptr<char> alive_ = std::make_shared<char>();
};

}  // namespace azt::app
