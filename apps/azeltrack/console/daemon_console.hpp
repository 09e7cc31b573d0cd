#pragma once
// What the web console sees and does, over the daemon's own parts (docs/web-api.md). Every
// change of a setting goes through the ConfigStore (validated, atomic, .bak) first and is applied
// to the running station only once it is saved, so what runs is always what a restart would load.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antenna/antenna_backend.hpp"
#include "azt/astro/ephemeris.hpp"
#include "azt/astro/sky_snapshot.hpp"
#include "azt/control/modes.hpp"
#include "calibration/calibration_runner.hpp"
#include "calibration/pointing_history.hpp"
#include "calibration/recorder.hpp"
#include "common/off_loop.hpp"
#include "config/config_store.hpp"
#include "config/daemon_config.hpp"
#include "console/console_model.hpp"
#include "console/moon_planner.hpp"
#include "console/settings_change.hpp"
#include "elements/element_feed.hpp"
#include "schedule/schedule_follower.hpp"
#include "station/clock_watch.hpp"
#include "station/direction_test.hpp"
#include "station/noise_runner.hpp"
#include "station/pointing_scanner.hpp"
#include "station/pol_follower.hpp"
#include "station/recent_events.hpp"
#include "station/satellite_tracker.hpp"
#include "station/sky_follower.hpp"
#include "station/station_commands.hpp"
#include "station/target_wait.hpp"

namespace azt::app {

/// The parts of the daemon the console works on; all owned by the daemon.
struct ConsoleParts {
  DaemonConfig& config;  ///< the running configuration (station, corrections, park, …)
  ConfigStore& store;
  const astro::Ephemeris& ephemeris;
  SkyFollower& sky;
  control::ModeController& modes;
  StationCommands& commands;  ///< the front door every motion command goes through
  AntennaBackend& antenna;
  SatelliteTracker* satellites;         ///< null: no satellite catalogue
  std::function<double()> monotonic_s;  ///< the control loop's clock
  std::function<double()> unix_s;       ///< UTC seconds since 1970
  nlohmann::json servers;               ///< where each server listens, for the state
  /// The station's hard inputs and the T/R sequencer ({"estop","limits","sequencer"}).
  std::function<nlohmann::json()> station_io;
  /// Where saves run: the daemon's worker thread (off the event loop), or run_inline in tests.
  Offload offload = run_inline;
  const RecentEvents* events = nullptr;   ///< refusals given to any source, for the state
  const RecentEvents* motions = nullptr;  ///< accepted motion commands and their sources
  std::function<void(const std::string&)> log = [](const std::string&) {};
  /// The GPS receiver's state (null when not given).
  std::function<nlohmann::json()> gps;
  /// The station's clock (null when not given: `time` is null).
  ClockWatch* clock = nullptr;
  /// The network links (null when not given: `network` is null).
  std::function<nlohmann::json()> network;
  /// The receiver of pointing scans (null when not given: `receiver` is off).
  std::function<nlohmann::json()> receiver;
  /// Pointing scans (null: none here, `scan` is idle and scans are refused).
  PointingScanner* scanner = nullptr;
  /// POST /api/restart: the daemon stops the motors and starts again (null: refused, 409).
  std::function<void(const std::string& who)> restart;
  /// The noise measurements' and the recording's actions: the answer, or nullopt for another
  /// action (recording_actions.cpp).
  std::optional<nlohmann::json> act_measurement(const std::string& action,
                                                const nlohmann::json& body,
                                                const std::string& source);
  /// POST /api/recording and /api/recording/stop (recording_actions.cpp).
  nlohmann::json act_recording(const std::string& action, const nlohmann::json& body,
                               const std::string& source);
  /// POST /api/hardware/direction-test (null: none here, 404).
  DirectionTest* direction_test = nullptr;
  /// The rig's Doppler and link (`radio`) and WSJT-X (`wsjtx`); null: off.
  std::function<nlohmann::json()> radio;
  std::function<nlohmann::json()> wsjtx;
  /// Where the element sets come from (null: no sources, no uploads; `satellites.sources` empty).
  ElementFeed* elements = nullptr;
  /// The satellite schedule's follower (null: none; `schedule` null, its routes 404).
  ScheduleFollower* schedule = nullptr;
  /// Noise measurements (null: none here, `noise` is idle and measurements are refused).
  NoiseRunner* noise = nullptr;
  /// Recording to CSV (null: none here, `recording` is idle and recordings are refused).
  Recorder* recorder = nullptr;
  /// recordings/ in the state directory, and the noise log's file; read off the loop.
  std::string recordings_dir{};
  std::string noise_log{};
  /// The calibration session and its scan log (null: none here, its routes 404).
  CalibrationRunner* calibration = nullptr;
  /// The models saved as [pointing] (with `calibration`).
  PointingHistory* pointing_history = nullptr;
  /// The polarisation axis's follower (null: no pol axis; `pol` null, POST /api/pol 404).
  PolFollower* pol = nullptr;
};

class DaemonConsole final : public ConsoleModel {
 public:
  explicit DaemonConsole(ConsoleParts parts)
      : p_(std::move(parts)),
        planner_({p_.config.sky, p_.config.mount.el_fixed, p_.offload, p_.unix_s}),
        wait_({p_.config.sky, p_.config.station.el_range.min_deg, p_.offload}),
        started_(p_.store.root()) {}

  nlohmann::json state() override;
  nlohmann::json config() override;
  nlohmann::json config_schema() override;
  nlohmann::json targets() override;
  nlohmann::json sky(double hours) override;
  nlohmann::json schedule() override;
  void upload_elements(std::string text, const std::string& source, ActDone done) override;
  void act(const std::string& action, const nlohmann::json& body, const std::string& source,
           ActDone done) override;
  void moon_windows(const std::string& query, ActDone done) override {
    planner_.answer(query, std::move(done));
  }
  void save_password_hash(const std::string& hash, ActDone done) override;
  void save_tokens(const nlohmann::json& tokens, ActDone done) override;
  std::optional<std::string> config_file_text() override;
  std::pair<unsigned, nlohmann::json> calibration_view(const std::string& route) override;
  std::optional<std::string> scan_log_csv() override;
  void import_scan_log(std::string text, const std::string& source, ActDone done) override;
  std::string utc_now_text() override;
  void import_config_file(const std::string& text, ActDone done) override;
  /// GET /api/recordings, /api/recordings/NAME, /api/noise/log (recording_actions.cpp).
  void read_later(const std::string& route, ActDone done) override;

 private:
  /// Sun, Moon and every target at one whole second, computed once per second.
  struct Snapshot {
    double unix_s = -1.0;
    nlohmann::json moon;
    nlohmann::json sun;
    std::vector<nlohmann::json> targets;  ///< {"name","kind","az_deg","el_deg"}
  };
  const Snapshot& snapshot();
  /// The Moon panel: position, distance, echo delay and Doppler for the band (and DX).
  nlohmann::json moon_json(const astro::TargetReport& r, const astro::SkySnapshot& sky) const;
  nlohmann::json target_json();
  [[nodiscard]] nlohmann::json satellites_json() const;
  [[nodiscard]] nlohmann::json control_json() const;

  /// The console's target body, parsed into the one request type (a malformed field: ApiError).
  static TargetRequest target_request(const nlohmann::json& body);
  nlohmann::json act_target(const nlohmann::json& body, const std::string& source);
  /// POST /api/scan: points at the source and starts a pointing scan (docs/calibration.md).
  nlohmann::json act_scan(const nlohmann::json& body, const std::string& source);
  /// POST /api/noise and /api/noise/stop (noise_actions.cpp).
  nlohmann::json act_noise(const std::string& action, const nlohmann::json& body,
                           const std::string& source);
  /// The noise measurements', the recording's and the calibration session's actions
  /// (calibration_actions.cpp).
  void act_measurement(const std::string& action, const nlohmann::json& body,
                       const std::string& source, ActDone done);
  /// POST /api/calibration/session, …/session/stop, …/apply, …/restore (calibration_actions.cpp).
  void act_calibration(const std::string& action, const nlohmann::json& body,
                       const std::string& source, ActDone done);
  /// The fit of the whole scan log with the model in use, or why there is none.
  [[nodiscard]] Result<calibration::PointingFit> calibration_fit() const;
  /// Saves `terms` as [pointing] and, once saved, appends `records` to the history.
  void save_pointing(const calibration::PointingTerms& terms,
                     const std::vector<nlohmann::json>& records, ActDone done);
  /// /api/state `calibration`: the session's state and the pointing model in use (`model`).
  [[nodiscard]] nlohmann::json calibration_json() const;
  /// A file beside the configuration (the state directory).
  [[nodiscard]] std::string state_file(const char* name) const;
  /// POST /api/recording and /api/recording/stop (recording_actions.cpp).
  nlohmann::json act_recording(const std::string& action, const nlohmann::json& body,
                               const std::string& source);
  /// POST /api/satellites/refresh: every element source fetched now.
  void act_satellites_refresh(const std::string& source, const ActDone& done);
  /// POST /api/hardware/…: the direction test or homing.
  void act_hardware(const std::string& action, const nlohmann::json& body,
                    const std::string& source, ActDone done);
  /// POST /api/hardware/direction-test {"axis"}: answered when the test ends (about 1.6 s).
  void act_direction_test(const nlohmann::json& body, const std::string& source, ActDone done);
  /// POST /api/schedule (the list replaced whole) and /api/schedule/resume (schedule_api.cpp).
  void act_schedule(const std::string& action, const nlohmann::json& body,
                    const std::string& source, ActDone done);
  /// POST /api/scan/apply: the last scan's offsets into [corrections] (saved atomically).
  void act_scan_apply(const nlohmann::json& body, ActDone done);
  // The settings: each validates the body at once (ApiError), then saves off the loop.
  void act_correction(const nlohmann::json& body, ActDone done);
  void act_band(const nlohmann::json& body, ActDone done);
  void act_dx(const nlohmann::json& body, ActDone done);
  void act_offsets(const nlohmann::json& body, ActDone done);
  void act_tilt(const nlohmann::json& body, ActDone done);
  void act_park(const nlohmann::json& body, ActDone done);
  /// PUT config/SECTION[/N] (settings_change.hpp): the keys checked against the schema, saved,
  /// the live ones applied; the answer lists which applied and which wait for a restart.
  void act_settings(const std::string& route, const nlohmann::json& body, ActDone done);
  nlohmann::json apply_settings(const SettingsChange& change);
  /// Brings the running station to the saved configuration's settings of one kind.
  void apply_live(LiveApply what);
  /// POST /api/pol {"mode", "angle_deg"} (pol_actions.cpp): through the front door's rules,
  /// saved as [pol] (the manual angle is not saved), then followed.
  void act_pol(const nlohmann::json& body, const std::string& source, ActDone done);
  /// /api/state `pol`: null without a pol axis (pol_actions.cpp).
  [[nodiscard]] nlohmann::json pol_json() const;
  /// /api/state `antenna.axes`: each axis's brake, motor readings and homing (axis_actions.cpp).
  [[nodiscard]] nlohmann::json axes_json() const;
  /// POST hardware/home {"axis"}: homes a pulse-counted axis (axis_actions.cpp).
  void act_home(const nlohmann::json& body, const std::string& source, const ActDone& done);
  /// POST time/servers {"servers": [...]}: chrony's upstream servers ([time] manage_chrony).
  void act_time_servers(const nlohmann::json& body, ActDone done);

  /// Saves `change` through the store off the loop; then, back on the loop, `apply` brings the
  /// running station to the saved configuration and gives the answer's fields. A refusal is a
  /// 400 naming `field` (503 while another program holds the file's lock).
  void save(const std::string& field, ConfigStore::Change change,
            std::function<nlohmann::json()> apply, ActDone done);
  [[nodiscard]] ApiError save_refusal(const std::string& field, std::string message) const;
  void apply_corrections(const control::PositionCorrections& corrections);

  ConsoleParts p_;
  MoonPlanner planner_;
  TargetWait wait_;
  Snapshot snapshot_;
  /// The file as the daemon started on it, and the saved settings that differ from it and wait
  /// for a restart (restart_needed.hpp), brought up to date after every save.
  toml::table started_;
  std::vector<std::string> restart_needed_;
  bool scan_apply_pending_ = false;     ///< a scan's apply is being saved: a second is refused
  bool pointing_save_pending_ = false;  ///< an apply or a restore is being saved
};

}  // namespace azt::app
