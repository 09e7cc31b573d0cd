#pragma once
// The daemon following the satellite schedule (docs/satellites.md "The schedule"): the plan of
// satellite_schedule.hpp, made again off the loop every few minutes and whenever the list, the
// catalogue or the site changes, and carried out step by step through the station's front door
// as the source "schedule": a satellite from its pre-position to its LOS, a STOP between passes,
// park slot 1 after the idle time, then the motors' power off until just before the next
// pre-position. Any other command (a console, a PC program) holds the schedule until an operator
// resumes it: the schedule never fights a person.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antenna/motor_power.hpp"
#include "common/off_loop.hpp"
#include "schedule/satellite_schedule.hpp"
#include "station/satellite_tracker.hpp"
#include "station/station_commands.hpp"

namespace azt::app {

/// What the hooks are told (schedule_hooks.hpp runs the programs).
enum class ScheduleEvent { PrePosition, Aos, Los, Park };
std::string_view to_string(ScheduleEvent event);

struct ScheduleFollowerParts {
  StationCommands& commands;
  const SatelliteTracker& satellites;  ///< the catalogue, and which satellite is followed
  MotorPower* power = nullptr;         ///< null: no [hardware.power] relay
  Offload plan_off_loop;               ///< where the pass searches run
  std::function<double()> unix_s;
  std::function<double()> monotonic_s;         ///< the control loop's clock, for the power's lead
  std::function<control::AzEl()> antenna_sky;  ///< where the antenna points, for a re-plan
  std::function<bool()> antenna_still;         ///< stopped: the power may go off
  /// A hook's moment, with the pass it is about (null for Park).
  std::function<void(ScheduleEvent, const schedule::Priority*, const PlannedPass*)> on_event;
  std::function<void(const std::string&)> log;
};

class ScheduleFollower {
 public:
  ScheduleFollower(ScheduleFollowerParts parts, std::vector<ScheduleEntryConfig> entries,
                   ScheduleSite site, schedule::ScheduleRules rules);

  /// A new priority list (the console saved [[schedule]]), site or catalogue: plan again.
  void set_entries(std::vector<ScheduleEntryConfig> entries);
  void set_observer(const astro::Observer& site);
  void catalogue_changed() { replan_due_ = true; }
  /// Every control tick: re-plans when due, carries out the step the time is in.
  void tick();
  /// Told of every accepted command: one not the schedule's (nor the configuration's start
  /// target) holds it.
  void on_command(const CommandSource& source);
  /// The operator hands the antenna back; refused (nullopt) when there is no schedule.
  std::optional<std::string> resume(const std::string& who);

  /// /api/state `schedule`: {"running", "held_by", "step", "next", "power", "problems"}; null
  /// without [[schedule]].
  [[nodiscard]] nlohmann::json state() const;
  /// GET /api/schedule: {"entries", "from", "hours", "plan", "passes"} (plan_json()).
  [[nodiscard]] nlohmann::json plan_view() const;

  static constexpr const char* kSourceName = "schedule";

 private:
  /// A step's identity, stable across re-plans: its kind and satellite.
  struct StepKey {
    std::optional<schedule::StepKind> kind;  ///< none: between steps
    std::string norad;
    bool operator==(const StepKey&) const = default;
  };
  void start_replan(double unix_s);
  [[nodiscard]] schedule::PlanStart plan_start(double unix_s) const;
  [[nodiscard]] const schedule::PlanStep* step_at(double unix_s) const;
  [[nodiscard]] StepKey key_of(const schedule::PlanStep* step) const;
  void enter(const schedule::PlanStep* step);
  void leave(const StepKey& left);
  void follow(const schedule::PlanStep& step);
  void command(const TargetRequest& request);
  void power_on();
  void keep_power(const schedule::PlanStep* step);
  [[nodiscard]] const schedule::Priority* priority_of(const schedule::PlanStep& step) const;
  [[nodiscard]] nlohmann::json step_json(const schedule::PlanStep* step) const;

  ScheduleFollowerParts p_;
  std::vector<ScheduleEntryConfig> entries_;
  ScheduleSite site_;
  schedule::ScheduleRules rules_;
  std::optional<SchedulePlan> plan_;
  std::vector<std::string> problems_;  ///< entries not in the catalogue, failed searches
  bool replan_due_ = true;
  bool planning_ = false;
  double next_replan_unix_s_ = 0.0;
  StepKey current_;
  std::optional<schedule::PlanStep> current_step_;  ///< the step carried out now
  std::optional<std::string> held_by_;
  double idle_since_unix_s_ = 0.0;
};

}  // namespace azt::app
