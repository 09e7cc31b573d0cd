#pragma once
// The running daemon: every part `serve` wires (the antenna, the station's front door, the
// protocol servers, the console) and the control loop that drives them on one Asio loop.
// wiring.cpp builds and connects the parts; control_loop.cpp runs the tick, the signals and the
// ways out. Private to the daemon room: the rest of the program sees daemon.hpp.

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "antenna/antenna_backend.hpp"
#include "antenna/motor_power.hpp"
#include "azt/linux/asio.hpp"
#include "azt/linux/gpio.hpp"
#include "azt/linux/serial_protocol_server.hpp"
#include "azt/linux/systemd_notify.hpp"
#include "azt/linux/tcp_protocol_server.hpp"
#include "azt/linux/udp_datagram_server.hpp"
#include "azt/linux/worker_thread.hpp"
#include "calibration/calibration_runner.hpp"
#include "calibration/pointing_history.hpp"
#include "calibration/recorder.hpp"
#include "common/off_loop.hpp"
#include "config/config_store.hpp"
#include "console/console_server.hpp"
#include "daemon/daemon.hpp"
#include "daemon/rate_limited_log.hpp"
#include "daemon/tick_stats.hpp"
#include "elements/element_feed.hpp"
#include "hands/hand_buttons.hpp"
#include "hands/hand_pad.hpp"
#include "radio/station_radio.hpp"
#include "schedule/schedule_follower.hpp"
#include "station/azel_dat_export.hpp"
#include "station/clock_watch.hpp"
#include "station/direction_test.hpp"
#include "station/gps_receiver.hpp"
#include "station/guarded_antenna.hpp"
#include "station/network_watch.hpp"
#include "station/noise_runner.hpp"
#include "station/pointing_scanner.hpp"
#include "station/pol_follower.hpp"
#include "station/power_receiver.hpp"
#include "station/recent_events.hpp"
#include "station/satellite_tracker.hpp"
#include "station/sequencer_runner.hpp"
#include "station/simulated_power.hpp"
#include "station/sky_follower.hpp"
#include "station/station_commands.hpp"
#include "station/station_service.hpp"

namespace azt::app {

class StationDaemon {
 public:
  using SteadyClock = std::chrono::steady_clock;

  /// Wires every part from the configuration; throws UsageError (nothing driven) when a server,
  /// a device or the start target cannot be had.
  StationDaemon(ConfigStore& store, const DaemonOptions& options);
  /// Finishes and joins both workers before any part is destroyed: a job still queued at a
  /// SIGTERM can then reach nothing that is gone, whatever it captured.
  ~StationDaemon();
  StationDaemon(const StationDaemon&) = delete;
  StationDaemon& operator=(const StationDaemon&) = delete;
  /// Runs until a signal (or --run-for); the exit code (daemon.hpp).
  int run();

 private:
  // wiring.cpp: the parts, from the configuration.
  std::unique_ptr<AntennaBackend> make_backend();
  std::unique_ptr<SequencerRunner> make_sequencer();
  /// The backend behind the E-stop, the limit switches and the latch file.
  std::unique_ptr<AntennaBackend> make_guarded(std::unique_ptr<AntennaBackend> inner);
  SatelliteSettings satellite_settings() const;
  /// [satellites] sources and file: the element feed over libcurl, the cache beside the
  /// configuration (the state directory).
  std::unique_ptr<ElementFeed> make_element_feed();
  // satellite_parts.cpp: the element feed, the schedule and the motors' power relay.
  /// [hardware.power]: the relay on its GPIO line (or the sim's); none when not set.
  std::unique_ptr<MotorPower> make_motor_power();
  [[nodiscard]] ScheduleSite schedule_site() const;
  /// [[schedule]] followed (always made: the console may write the first list).
  std::unique_ptr<ScheduleFollower> make_schedule();
  /// A step of the schedule begun or ended: the recent events, and the hooks.
  void schedule_event(HookEvent event, const schedule::Priority* sat, const PlannedPass* pass);
  /// A path of the configuration relative to its directory, absolute.
  std::string beside_config(const std::string& path) const;
  /// Where the mount's azimuth is (for choosing a pass's wrap side), or the configured start.
  double mount_az() const;
  /// UTC seconds since 1970, from the system clock.
  double unix_now_s() const;
  /// What may block goes to the worker; its result comes back to the loop (off_loop.hpp).
  Offload off_loop();
  double now_s() const;
  void start_target();
  /// [gps] use_position: saves a surveyed site as [station] lat/lon/alt (off the loop) and, once
  /// saved, points from it; `done(false)` when the save failed (logged).
  void adopt_site(const gnss::Site& site, std::function<void(bool)> done);
  /// [time]: chrony, the kernel and the RTC watched on the clock's own worker.
  std::unique_ptr<ClockWatch> make_clock_watch();
  /// Posts to the status worker (the clock's and the network's looks, azel.dat).
  Offload status_off_loop();
  /// [export] azel_dat: WSJT-X's azel.dat every second.
  std::unique_ptr<AzelDatExport> make_azel_dat_export();
  /// [receiver] source = "sim": the simulated receiver, hearing the sim backend's true beam.
  void simulate_receiver();
  /// [radio], [wsjtx]: the rig kept on frequency and WSJT-X heard (radio/station_radio.hpp).
  std::unique_ptr<StationRadio> make_radio();
  /// WSJT-X's DX grid as the running DX (not saved).
  void follow_dx_grid(const std::string& grid);
  void open_servers();
  void open_console();
  /// A refusal a client was given: in the journal (at most 10 lines a minute per client) and in
  /// the console's recent events.
  void control_event(const std::string& text);
  /// An accepted motion command: in the journal (at most 10 lines a minute per source, the rest
  /// counted) and in the console's recent commands, one line per source and kind of command.
  void motion_event(const CommandSource& source, const CommandRecord& record);
  // pol_parts.cpp: the polarisation axis's follower.
  /// None when the antenna has no pol axis.
  std::unique_ptr<PolFollower> make_pol_follower();
  /// Before the antenna's tick: the pol axis's demand for it.
  void pol_tick();
  // control_loop.cpp: the tick, the signals, the ways out.
  void arm_tick();
  void tick();
  void report_faults();
  /// While a pointing scan runs: the position to demand (the source plus the scan's offset),
  /// ending the scan on any other command or a fault; otherwise `source` as it is.
  std::optional<control::AzEl> scan_aim(const std::optional<control::AzEl>& source);
  /// After the antenna's tick: the scan sees the antenna and the receiver's readings.
  void scan_tick(double now, const std::optional<control::AzEl>& source);
  // noise_parts.cpp: noise measurements (station/noise_runner.hpp) and their log.
  static constexpr const char* kNoiseLogFile = "noise-log.jsonl";  ///< beside the configuration
  std::unique_ptr<NoiseRunner> make_noise_runner();
  void log_noise(nlohmann::json record);
  /// The demand while a noise measurement runs: the source plus its offset.
  std::optional<control::AzEl> noise_aim(const std::optional<control::AzEl>& source);
  void noise_tick(double now, const std::optional<control::AzEl>& source);
  // recording_parts.cpp: recording to CSV (calibration/recorder.hpp), written on the worker.
  static constexpr const char* kRecordingsDir = "recordings";  ///< beside the configuration
  std::unique_ptr<Recorder> make_recorder();
  /// After the antenna's tick: a row of `demand`, the reading and the power when one is due.
  void recording_tick(double now, const control::Demand& demand);
  // calibration_parts.cpp: the calibration session, its scan log and the models' history.
  static constexpr const char* kScanLogFile = "scan-log.csv";  ///< beside the configuration
  static constexpr const char* kPointingHistoryFile = "pointing-history.jsonl";
  static constexpr const char* kCalibrationSessionFile = "calibration-session.json";
  std::unique_ptr<CalibrationRunner> make_calibration_runner();
  Result<std::string> point_for_calibration(const std::string& name);
  void append_scan_rows(const std::vector<calibration::ScanLogEntry>& rows);
  /// The running session's record written atomically, or (null) removed; on the worker.
  void keep_calibration(const nlohmann::json& record);
  /// A session the file says was running is started again from its request.
  void resume_calibration();
  void calibration_tick(double now);
  /// An exception escaped a handler: the loop's state is unknown, so the station goes safe and
  /// the process exits (systemd restarts it, motionless until a client asks).
  void fail_safe(const std::string& why);
  void shutdown(const std::string& why);
  /// Stops as a signal would, then run() returns linux_os::kExitRestart (the console's Restart).
  void restart(const std::string& who);
  /// restart() in a moment, from a handler that must answer first.
  void restart_soon(const std::string& who);

  DaemonConfig config_;  ///< the running configuration; the console changes parts of it
  ConfigStore& store_;
  DaemonOptions options_;
  SteadyClock::time_point start_;
  boost::asio::io_context io_;
  /// Password checks, configuration saves, the E-stop latch file: what may block, off the loop.
  /// Its jobs' work halves touch only what they captured (by value), and their done halves run
  /// only on the loop; ~StationDaemon finishes it before any part is destroyed.
  linux_os::WorkerThread worker_{io_};
  /// chronyc and D-Bus may take seconds: the looks at the clock and the network queue here, not
  /// ahead of a save or a login.
  linux_os::WorkerThread status_worker_{io_};
  /// Element downloads may stall for their whole timeout: on a worker of their own, so a login
  /// or a save never waits behind one. Set, a running download is abandoned (a stop).
  std::atomic<bool> downloads_cancelled_{false};
  linux_os::WorkerThread download_worker_{io_};
  std::unique_ptr<astro::Ephemeris> ephemeris_;
  SkyFollower sky_;
  control::ModeController modes_;
  std::unique_ptr<linux_os::GpioProvider> gpio_;
  std::unique_ptr<linux_os::GpioInput> ptt_;
  std::unique_ptr<SequencerRunner> sequencer_;
  GuardedAntenna* guard_ = nullptr;
  /// The `sim` backend's plants (the truth its simulated receiver hears through); declared
  /// before antenna_, whose making sets it.
  std::shared_ptr<const sim::PlantRig> sim_truth_;
  std::unique_ptr<AntennaBackend> antenna_;
  SatelliteTracker satellites_;
  std::unique_ptr<ElementFeed> elements_;
  RateLimitedLog log_;
  RecentEvents events_;
  RecentEvents motions_;                      ///< accepted motion commands, with their sources
  std::unique_ptr<GpsReceiver> gps_;          ///< [gps]: gpsd, the GPS state and the site survey
  std::unique_ptr<ClockWatch> clock_;         ///< [time]: is the clock to be trusted
  std::unique_ptr<NetworkWatch> network_;     ///< the links, for the console
  std::unique_ptr<AzelDatExport> azel_dat_;   ///< [export] azel_dat; none when not set
  std::unique_ptr<PowerReceiver> receiver_;   ///< [receiver]: the power readings of scans
  std::unique_ptr<PointingScanner> scanner_;  ///< a pointing scan, while one runs
  std::unique_ptr<NoiseRunner> noise_;        ///< a noise measurement, while one runs
  std::unique_ptr<Recorder> recorder_;        ///< recording to CSV, while one runs
  PointingHistory pointing_history_;          ///< the models saved as [pointing]
  std::unique_ptr<CalibrationRunner> calibration_;  ///< the calibration session, while one runs
  std::unique_ptr<StationRadio> radio_;             ///< [radio] and [wsjtx]: the rig and WSJT-X
  std::unique_ptr<MotorPower> power_;               ///< [hardware.power]; none when not set
  std::unique_ptr<PolFollower> pol_;  ///< [mount.pol]'s follower; none without a pol axis
  std::string pol_dx_grid_;           ///< the DX grid its Dpol nodes are for
  StationCommands commands_;
  std::unique_ptr<HandButtons>
      buttons_;                   ///< [gpio] button_*: the buttons at the mast; none unwired
  std::unique_ptr<HandPad> pad_;  ///< [gamepad]: a game pad at the mast; none unconfigured
  DirectionTest direction_test_;  ///< the console's direction test of one axis, while one runs
  std::unique_ptr<ScheduleHooks> hooks_;        ///< [hooks]: the programs run at its events
  std::unique_ptr<ScheduleFollower> schedule_;  ///< [[schedule]]: the station working by itself
  StationService service_;
  boost::asio::signal_set signals_;
  boost::asio::steady_timer timer_;
  SteadyClock::duration period_;
  SteadyClock::time_point deadline_;
  TickStats stats_;
  linux_os::SystemdNotifier notifier_;
  std::unique_ptr<linux_os::TcpProtocolServer> rotctld_;
  std::vector<std::unique_ptr<linux_os::SerialProtocolServer>> serial_;
  std::unique_ptr<linux_os::UdpDatagramServer> pstrotator_;
  std::unique_ptr<ConsoleServer> console_;
  std::vector<std::string> last_faults_;
  std::string last_summary_;  ///< mode, owner and fault count at the last tick
  bool stopping_ = false;
  bool restart_requested_ = false;
  /// [target] name is a satellite the catalogue does not hold yet (or whose elements are too
  /// old): tried again at each publish until it is followed or another command is given.
  bool start_waits_for_elements_ = false;
};

}  // namespace azt::app
