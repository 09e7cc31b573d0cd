#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "azt/control/modes.hpp"
#include "azt/control/station_setup.hpp"
#include "azt/linux/gpio.hpp"
#include "azt/linux/hamlib_rotator.hpp"
#include "azt/linux/hub_serial_link.hpp"
#include "azt/linux/pwm_hbridge.hpp"
#include "azt/proto/target_limits.hpp"
#include "azt/sequencer/tr_sequencer.hpp"
#include "azt/sim/station_sim.hpp"
#include "config/config_choice.hpp"
#include "config/export_config.hpp"
#include "config/gamepad_config.hpp"
#include "config/gps_config.hpp"
#include "config/hardware_config.hpp"
#include "config/hooks_config.hpp"
#include "config/mount_config.hpp"
#include "config/radio_config.hpp"
#include "config/receiver_config.hpp"
#include "config/schedule_config.hpp"
#include "config/sim_config.hpp"
#include "config/sky_config.hpp"
#include "config/time_config.hpp"
#include "config/wsjtx_config.hpp"

namespace azt::app {

/// The serial protocols PC programs speak to the station ([[serial]] protocol).
enum class SerialProtocol { Gs232a, Gs232b, EasyComm1, EasyComm2, Spid, Rot1Prog };
inline constexpr ConfigChoices<SerialProtocol, 6> kSerialProtocols{
    {{"gs232a", SerialProtocol::Gs232a},
     {"gs232b", SerialProtocol::Gs232b},
     {"easycomm1", SerialProtocol::EasyComm1},
     {"easycomm2", SerialProtocol::EasyComm2},
     {"spid", SerialProtocol::Spid},
     {"rot1prog", SerialProtocol::Rot1Prog}}};

/// The antenna behind the station ([antenna] backend).
enum class BackendKind { Sim, Hamlib, Pwm, Hardware };
inline constexpr ConfigChoices<BackendKind, 4> kBackendKinds{{{"sim", BackendKind::Sim},
                                                              {"hamlib", BackendKind::Hamlib},
                                                              {"pwm", BackendKind::Pwm},
                                                              {"hardware", BackendKind::Hardware}}};

struct SerialServerConfig {
  SerialProtocol protocol = SerialProtocol::Gs232b;
  /// "gs232b" as the configuration spells it, for logs and the console.
  [[nodiscard]] std::string_view protocol_name() const {
    return name_of(kSerialProtocols, protocol);
  }
  std::string device;  ///< "pty:/path" or a device path
  unsigned baud = 9600;
};

struct NetServerConfig {
  std::string bind = "127.0.0.1";
  unsigned short port = 0;  ///< 0: disabled
};

/// [pwm]: the IBT-2 H-bridges on one sysfs PWM chip (the `pwm` backend, and `hardware` axes with
/// drive = "pwm"; docs/hardware.md), with the chip, frequency and dead time shared and two
/// channels each; the pol axis's bridge is used only by a [hardware.pol] with drive = "pwm".
struct PwmConfig {
  linux_os::PwmHBridgeConfig az;
  linux_os::PwmHBridgeConfig el{"/sys/class/pwm/pwmchip0", 2, 3, 1000.0, 0.1};
  linux_os::PwmHBridgeConfig pol{"/sys/class/pwm/pwmchip0", 4, 5, 1000.0, 0.1};
  /// The bridge of HardwareAxisConfig::name: "az", "el" or "pol" (nothing else is an axis).
  [[nodiscard]] const linux_os::PwmHBridgeConfig& of(const std::string& axis) const {
    if (axis == "az") return az;
    return axis == "pol" ? pol : el;
  }
};

/// [gpio] button_*: the buttons at the mast (docs/hardware.md, "Buttons and a game pad"), each a
/// push button to ground (pull-up) unless `buttons_active_low` is false. Absent: not wired.
struct ButtonsConfig {
  std::optional<linux_os::GpioLineSpec> cw;
  std::optional<linux_os::GpioLineSpec> ccw;
  std::optional<linux_os::GpioLineSpec> up;
  std::optional<linux_os::GpioLineSpec> down;
  std::optional<linux_os::GpioLineSpec> stop;
  std::optional<linux_os::GpioLineSpec> park;
  double debounce_s = 0.03;
  double speed = 1.0;  ///< a jog button's speed, a fraction of the axis's full rate
  int park_slot = 1;   ///< the [[park]] slot PARK goes to
  [[nodiscard]] std::vector<const linux_os::GpioLineSpec*> lines() const;
};

/// [gpio]: the station's GPIO lines (docs/hardware.md). Absent lines are not wired.
struct GpioConfig {
  std::string chip = "gpiochip0";  ///< the chip of lines given as bare numbers
  std::optional<linux_os::GpioLineSpec> estop;
  std::optional<linux_os::GpioLineSpec> az_ccw_limit;
  std::optional<linux_os::GpioLineSpec> az_cw_limit;
  std::optional<linux_os::GpioLineSpec> el_down_limit;
  std::optional<linux_os::GpioLineSpec> el_up_limit;
  std::optional<linux_os::GpioLineSpec> pol_ccw_limit;  ///< the pol axis's ([mount.pol])
  std::optional<linux_os::GpioLineSpec> pol_cw_limit;
  std::optional<linux_os::GpioLineSpec> ptt;
  std::vector<linux_os::GpioLineSpec> sequencer;  ///< one per [sequencer] output, keying order
  std::string estop_latch_file;  ///< empty: "estop.latched" beside the configuration file
  ButtonsConfig buttons;

  /// Every configured line, inputs first (the buttons last of them), then the sequencer outputs.
  [[nodiscard]] std::vector<const linux_os::GpioLineSpec*> lines() const;
  [[nodiscard]] bool any_line() const { return !lines().empty(); }
};

/// [satellites]: the element-set catalogue the daemon tracks satellites from (docs/satellites.md).
struct SatellitesConfig {
  std::string file;        ///< TLE or OMM; relative to the configuration's directory; empty: none
  std::string mask = "0";  ///< horizon: one elevation, or "AZ:MIN_EL,…" sectors
  /// The satellite antenna's half-power beamwidth: a moment of a pass beyond half of it from the
  /// satellite counts as lost (the pass planner's loss, docs/satellites.md).
  double beamwidth_deg = 20.0;
  /// Element sets from the network (docs/satellites.md): the URLs in order and how they are
  /// fetched.
  std::vector<std::string> sources;
  double refresh_h = 12.0;
  double stale_days = 14.0;   ///< passes marked stale beyond this element age
  double refuse_days = 60.0;  ///< not tracked beyond this element age
  /// The schedule parks after this long with nothing to do (then powers the motors off).
  double idle_park_min = 10.0;
  double min_el_deg = 10.0;  ///< the console's pass lists leave out lower passes
  std::string ca_file;       ///< empty: the system's CAs
  std::string proxy;         ///< empty: the environment's, or none
  double connect_timeout_s = 20.0;
  double timeout_s = 120.0;
  double max_mb = 32.0;
  long max_redirects = 5;
};

/// [web]: the console's HTTP server and who may act through it (docs/web-api.md).
/// A bearer token's record in `[[token]]` (the token itself is kept nowhere).
struct WebToken {
  std::string label;
  std::string sha256;
  std::string created_utc;
};

struct WebConfig {
  std::string bind = "127.0.0.1";
  unsigned short port = 8080;    ///< 0: disabled
  std::string password_hash;     ///< libsodium Argon2id string; empty: generated at first start
  std::string api_token_sha256;  ///< hex SHA-256 of the scripts' bearer token; empty: none
  std::vector<std::string> allowed_hosts;  ///< Host names besides IP literals and localhost
  std::vector<WebToken> tokens;            ///< [[token]]
};

/// Everything `serve` reads (docs/configuration.md).
struct DaemonConfig {
  SkyConfig sky;                  ///< where the station is and what it can point at
  MountConfig mount;              ///< [mount.az] / [mount.el] / [mount.pol]
  control::PolSettings pol;       ///< [pol]: what the polarisation axis follows
  control::StationSetup station;  ///< what the controller knows, for every backend
  sim::PlantSetup sim;            ///< [sim.*]: the simulated plants (the `sim` backend only)
  /// [sim.az] / [sim.el]: the controller's brake timing and motor trips for the plants' brake and
  /// winding (the `sim` backend only).
  std::array<sim::AxisMotorControl, 2> sim_motors{};
  SimHubConfig sim_hub;                    ///< [sim] hub: the plain model or the hub firmware
  SimReceiverConfig sim_receiver;          ///< [sim.receiver]: for [receiver] source = "sim"
  std::string start_target = "moon";       ///< [target] name: what to track at start, or "stop"
  BackendKind backend = BackendKind::Sim;  ///< [antenna] backend
  linux_os::HamlibConfig hamlib;
  linux_os::HubSerialConfig hub;  ///< [hub]: the EncoderHub's serial device (`pwm` backend)
  PwmConfig pwm;
  GpioConfig gpio;
  std::optional<GamepadConfig> gamepad;  ///< [gamepad]: a game pad at the mast
  HardwareConfig hardware;  ///< [hardware.az] / [hardware.el] / [hardware.pol] (`hardware`)
  SatellitesConfig satellites;
  std::vector<ScheduleEntryConfig> schedule;  ///< [[schedule]], highest priority first
  HooksConfig hooks;                          ///< [hooks]: programs run at the schedule's events
  GpsConfig gps;                              ///< [gps]: the receiver through gpsd
  RadioConfig radio;                          ///< [radio], [[satellites.transmitter]]: the rig
  WsjtxConfig wsjtx;                          ///< [wsjtx]: WSJT-X's UDP messages
  ReceiverConfig receiver;                    ///< [receiver]: the power readings of pointing scans
  TimeConfig time;       ///< [time]: chrony watched, its servers set from the console
  ExportConfig exports;  ///< [export]: files for other programs (azel.dat)
  NetServerConfig rotctld{"127.0.0.1", 4533};
  /// A rotctld client silent this long is disconnected (0: never); Gpredict polls every second.
  double rotctld_idle_timeout_s = 600.0;
  std::vector<SerialServerConfig> serial;
  NetServerConfig pstrotator{"127.0.0.1", 12000};
  WebConfig web;
  /// [sequencer]: the T/R chain (the seed's default when the table is absent).
  sequencer::SequencerConfig sequencer = sequencer::SequencerConfig::seed_default();
  unsigned short pstrotator_reply_port = 12001;  ///< 0: reply to the sender's port
  std::array<control::ParkSlot, control::ModeController::kParkSlots> park;
  control::OutOfRangePolicy out_of_range = control::OutOfRangePolicy::Hold;
  std::string log_level = "info";
  bool jog_enabled = true;

  /// Where the axes are believed to be before the first reading: the simulated plants' start
  /// on the `sim` backend, otherwise the station's own belief (StationSetup::believed_start).
  [[nodiscard]] control::AzEl start_mount() const;
  /// The simulated station: this station on the [sim.*] plants.
  [[nodiscard]] sim::StationSimSetup simulated() const { return {station, sim, sim_motors}; }
  /// The targets PC programs may send: the travel in sky terms, azimuth in any convention
  /// clients use (−180..450).
  [[nodiscard]] proto::TargetLimits target_limits() const;
};

/// Parses and validates; throws UsageError naming the key and its line.
DaemonConfig daemon_config_from(const ConfigFile& file);

DaemonConfig load_daemon_config(const std::string& path);

/// The commented configuration a first run writes: the simulated antenna tracking the Moon,
/// every server on 127.0.0.1.
std::string default_config_text();

}  // namespace azt::app
