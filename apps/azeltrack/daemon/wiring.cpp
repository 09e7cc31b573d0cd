// The daemon's wiring: each part built from the configuration and connected to the others, the
// station's front door shared by the console and every protocol server (docs/architecture.md).
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "antenna/axis_devices.hpp"
#include "azt/astro/maidenhead.hpp"
#include "azt/linux/atomic_file.hpp"
#include "azt/linux/clock_probe.hpp"
#include "azt/linux/libgpiod_lines.hpp"
#include "azt/proto/pstrotator.hpp"
#include "azt/proto/sessions.hpp"
#include "azt/timekeeping/ntp_servers.hpp"
#include "azt/track/pass_plan.hpp"
#include "azt/util/valid_utf8.hpp"
#include "common/horizon_mask_option.hpp"
#include "common/program_version.hpp"
#include "common/sky_report.hpp"
#include "common/sky_setup.hpp"
#include "common/target_request.hpp"
#include "common/usage_error.hpp"
#include "daemon/station_daemon.hpp"

namespace azt::app {
namespace {

/// The station's 6-character locator for rotctld's get_info (the configured grid may have 4 to
/// 10 characters, or come from lat/lon): the square programs and operators exchange.
std::string station_locator(const astro::Observer& observer) {
  auto grid = astro::encode_locator(observer.lat_deg, observer.lon_deg, 6);
  return grid ? *grid : "(no locator)";
}

/// A client's bytes may be in a log line: valid UTF-8, no control characters, a bounded length.
std::string log_safe(const std::string& text) {
  std::string line = valid_utf8(text.substr(0, 240));
  // As unsigned: char is signed on x86-64 and unsigned on arm64, and UTF-8's bytes are >= 0x80.
  std::replace_if(
      line.begin(), line.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }, ' ');
  return line;
}

std::unique_ptr<proto::ProtocolSession> serial_session(const SerialServerConfig& c,
                                                       proto::RotatorService& service,
                                                       const proto::TargetLimits& limits) {
  const std::string client = std::string(c.protocol_name()) + " " + c.device;
  proto::SpidConfig spid;
  switch (c.protocol) {
    case SerialProtocol::Gs232a:
      return proto::make_gs232_session(service, client, proto::Gs232Variant::A, limits);
    case SerialProtocol::Gs232b:
      return proto::make_gs232_session(service, client, proto::Gs232Variant::B, limits);
    case SerialProtocol::EasyComm1:
      return proto::make_easycomm_session(service, client, proto::EasyCommVersion::One, limits);
    case SerialProtocol::EasyComm2:
      return proto::make_easycomm_session(service, client, proto::EasyCommVersion::Two, limits);
    case SerialProtocol::Rot1Prog:
      spid.dialect = proto::SpidDialect::Rot1Prog;
      break;
    case SerialProtocol::Spid:
      spid.dialect = proto::SpidDialect::Rot2Prog;
      break;
  }
  return proto::make_spid_session(service, client, spid);
}

}  // namespace

double StationDaemon::unix_now_s() const {
  if (options_.utc_start_unix_s) return *options_.utc_start_unix_s + now_s();
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

StationDaemon::StationDaemon(ConfigStore& store, const DaemonOptions& options)
    : config_(store.config()),
      store_(store),
      options_(options),
      start_(SteadyClock::now()),
      ephemeris_(open_ephemeris(config_.sky.settings.ephemeris)),
      sky_(*ephemeris_, config_.sky),
      modes_(config_.park, config_.out_of_range, config_.station.el_range.min_deg),
      gpio_(config_.gpio.any_line() || config_.hardware.uses_gpio()
                ? linux_os::make_libgpiod_provider(io_)
                : nullptr),
      sequencer_(make_sequencer()),
      antenna_(make_guarded(make_backend())),
      satellites_(satellite_settings(), [](const std::string& line) { spdlog::info("{}", line); }),
      commands_(StationCommandParts{
          modes_, *antenna_, sky_, &satellites_, config_.target_limits(), config_.station.el_range,
          [this] { return now_s(); }, [this] { return unix_now_s(); }, config_.start_mount().az_deg,
          [this](const CommandSource& source, const CommandRecord& record) {
            motion_event(source, record);
          },
          [this](const CommandSource& source, const Refusal& refusal) {
            control_event(source.name + ": refused: " + refusal.reason);
          }}),
      direction_test_(
          DirectionTestParts{*antenna_, commands_, modes_,
                             [this] {
                               return sequencer_->motion_hold() || sequencer_->transmitting() ||
                                      (radio_ && radio_->motion_hold());
                             },
                             [this] { return now_s(); }, config_.mount.el_fixed.has_value()}),
      service_(
          commands_, modes_, *antenna_, [this] { return now_s(); },
          // The locator first: Hamlib shows 63 characters of it (format_get_info).
          "azeltrack " + std::string(program_version()) + " at " +
              station_locator(config_.sky.settings.observer) + ": " + antenna_->describe(),
          [this](const std::string& line) { control_event(line); }),
      // SIGHUP too: a closed terminal must stop the motors, not kill the process mid-move.
      signals_(io_, SIGINT, SIGTERM, SIGHUP),
      timer_(io_),
      period_(std::chrono::duration_cast<SteadyClock::duration>(
          std::chrono::duration<double>(config_.station.tick_s))) {
  power_ = make_motor_power();
  if (!config_.gpio.buttons.lines().empty()) {
    buttons_ = std::make_unique<HandButtons>(config_.gpio.buttons, *gpio_, commands_,
                                             [this] { return now_s(); });
  }
  pad_ = make_hand_pad(
      io_, config_.gamepad, commands_, [this] { return now_s(); },
      [](const std::string& line) { spdlog::info("{}", line); });
  gps_ = std::make_unique<GpsReceiver>(
      io_, GpsReceiverParts{config_.gps, [this] { return now_s(); },
                            [this] { return modes_.mode() == control::Mode::Track; },
                            [this](const gnss::Site& site, std::function<void(bool)> done) {
                              adopt_site(site, std::move(done));
                            },
                            [](const std::string& line) { spdlog::info("{}", line); }});
  elements_ = make_element_feed();
  clock_ = make_clock_watch();
  network_ = std::make_unique<NetworkWatch>(
      io_, NetworkWatchParts{5.0, status_off_loop(), [] { return read_network_reading(); },
                             [](const std::string& line) { spdlog::info("{}", line); }});
  azel_dat_ = make_azel_dat_export();
  receiver_ = std::make_unique<PowerReceiver>(
      io_, config_.receiver, [this] { return now_s(); },
      [](const std::string& line) { spdlog::warn("{}", line); });
  if (config_.receiver.source == ReceiverConfig::Source::Sim) simulate_receiver();
  scanner_ = std::make_unique<PointingScanner>(
      config_.receiver.source == ReceiverConfig::Source::None ? nullptr : &receiver_->feed());
  noise_ = make_noise_runner();
  recorder_ = make_recorder();
  calibration_ = make_calibration_runner();
  radio_ = make_radio();
  pol_ = make_pol_follower();
  schedule_ = make_schedule();
}

std::unique_ptr<StationRadio> StationDaemon::make_radio() {
  if (!config_.radio.has_rig() && !config_.wsjtx.listen) return nullptr;
  return std::make_unique<StationRadio>(
      io_, StationRadioParts{
               config_.radio, config_.wsjtx, *ephemeris_, config_.sky, [this] { return now_s(); },
               [this] { return unix_now_s(); },
               [this]() -> std::optional<SatelliteNow> {
                 if (!commands_.tracking_satellite()) return std::nullopt;
                 const auto s = satellites_.status(unix_now_s());
                 if (!s.is_object() || !s.contains("range_rate_km_s")) return std::nullopt;
                 return SatelliteNow{s.value("norad", ""), s["range_rate_km_s"].get<double>()};
               },
               [this](const std::string& grid) { follow_dx_grid(grid); },
               [](const std::string& line) { spdlog::info("{}", line); }});
}

void StationDaemon::follow_dx_grid(const std::string& grid) {
  if (grid == config_.sky.settings.dx_grid) return;
  try {
    config_.sky.settings.dx = observer_from_grid(grid, 0.0);
    config_.sky.settings.dx_grid = grid;
    spdlog::info("wsjtx: DX grid {} (from WSJT-X, not saved)", grid);
  } catch (const UsageError& e) {
    log_.info("wsjtx dx", "wsjtx: DX grid '" + log_safe(grid) + "' not used: " + e.what(), now_s());
  }
}

void StationDaemon::simulate_receiver() {
  SimulatedPowerParts parts;
  parts.receiver = config_.sim_receiver;
  parts.mount_errors = config_.sim.pointing_errors;
  parts.sky_at = [this](double unix_s) {
    return sky_snapshot(*ephemeris_, config_.sky.settings,
                        astro::UtcInstant::from_unix_seconds(unix_s));
  };
  // The simulated encoders read the shafts true: the beam is the shafts through the mount's
  // errors, whatever [corrections] the operator sets on top.
  parts.shafts_deg = [truth = sim_truth_]() -> std::optional<control::AzEl> {
    if (!truth) return std::nullopt;
    return control::AzEl{truth->plants().az().shaft_deg(), truth->plants().el().shaft_deg()};
  };
  auto power = std::make_shared<SimulatedPower>(std::move(parts));
  receiver_->simulate([this, power] { return power->read_db(unix_now_s()); },
                      config_.sim_receiver.receiver.rate_hz);
}

std::unique_ptr<AzelDatExport> StationDaemon::make_azel_dat_export() {
  if (config_.exports.azel_dat.empty()) return nullptr;
  return std::make_unique<AzelDatExport>(
      io_, AzelDatParts{
               config_.exports.azel_dat, *ephemeris_, config_.sky, [this] { return unix_now_s(); },
               [this]() -> std::optional<astro::Target> {
                 const auto& t = sky_.target();
                 const bool body = t && (t->kind == astro::Target::Kind::Moon ||
                                         t->kind == astro::Target::Kind::Sun);
                 if (modes_.mode() != control::Mode::Track || !t || body) return {};
                 return *t;
               },
               [this] { return sequencer_->transmitting(); }, status_off_loop(),
               linux_os::publish_file, [](const std::string& line) { spdlog::info("{}", line); },
               config_.exports.azel_dat_pol_line});
}

Offload StationDaemon::status_off_loop() {
  return [this](std::function<void()> work, std::function<void()> done) {
    status_worker_.post(std::move(work), std::move(done));
  };
}

std::unique_ptr<ClockWatch> StationDaemon::make_clock_watch() {
  const TimeConfig& t = config_.time;
  const linux_os::ClockProbeConfig probe{t.chronyc, t.chrony_socket, 5.0, t.rtc};
  return std::make_unique<ClockWatch>(
      io_,
      ClockWatchParts{
          t, [this] { return now_s(); }, status_off_loop(),
          [probe] { return linux_os::probe_clock(probe); },
          [probe, file = t.sources_file](const std::vector<std::string>& servers) -> Result<bool> {
            auto written =
                linux_os::write_file_atomically(file, timekeeping::chrony_sources_text(servers));
            if (!written) return written.error();
            auto reloaded = linux_os::reload_chrony_sources(probe);
            if (!reloaded) return fail("saved in " + file + ", but " + reloaded.error().message);
            return true;
          },
          [file = t.sources_file] {
            const auto text = linux_os::read_file(file);
            return text ? timekeeping::servers_in_sources(text.value())
                        : std::vector<std::string>{};
          },
          [](const std::string& line) { spdlog::info("{}", line); }});
}

void StationDaemon::adopt_site(const gnss::Site& site, std::function<void(bool)> done) {
  ConfigStore::Change change = [site](toml::table& root) {
    if (!root.contains("station")) root.insert("station", toml::table{});
    toml::table* station = root["station"].as_table();
    if (station == nullptr) throw UsageError("[station] is not a table");
    set_station_position(*station, site.lat_deg, site.lon_deg, site.alt_m);
  };
  store_.save_off_loop(
      off_loop(), std::move(change),
      [this, site, done = std::move(done)](Result<std::vector<std::string>> notices) {
        if (!notices) {
          spdlog::warn("gps: the surveyed position was not saved: {}", notices.error().message);
          done(false);
          return;
        }
        for (const auto& notice : notices.value()) spdlog::warn("{}", notice);
        config_.sky = store_.config().sky;
        sky_.refollow();  // computed for the new place
        satellites_.set_site(config_.sky.settings.observer);
        if (schedule_) schedule_->set_observer(config_.sky.settings.observer);
        spdlog::info("gps: the station is at {:.6f} {:.6f} {:.1f} m (surveyed, saved)",
                     site.lat_deg, site.lon_deg, site.alt_m);
        done(true);
      });
}

std::unique_ptr<AntennaBackend> StationDaemon::make_backend() {
  if (config_.backend == BackendKind::Hamlib) return make_hamlib_backend(config_);
  if (config_.backend == BackendKind::Pwm) return make_pwm_backend(io_, config_);
  if (config_.backend == BackendKind::Hardware) {
    return make_hardware_backend(io_, config_, HardwarePorts::linux_devices(gpio_.get(), start_));
  }
  return make_sim_backend(config_, &sim_truth_);
}

std::unique_ptr<SequencerRunner> StationDaemon::make_sequencer() {
  std::vector<std::unique_ptr<linux_os::GpioOutput>> outputs;
  for (const auto& spec : config_.gpio.sequencer) {
    // De-energized at once: whatever an earlier run left keyed is released first.
    auto line = gpio_->output(spec, false);
    if (!line) throw UsageError(line.error().message);
    outputs.push_back(std::move(line).value());
  }
  auto runner = std::make_unique<SequencerRunner>(
      io_, config_.sequencer, std::move(outputs), [this] { return now_s(); },
      [](const std::string& line) { spdlog::info("{}", line); });
  if (config_.gpio.ptt) {
    auto ptt = gpio_->input(*config_.gpio.ptt, linux_os::GpioBias::PullUp,
                            [r = runner.get()](bool on) { r->set_ptt(on); });
    if (!ptt) throw UsageError(ptt.error().message);
    ptt_ = std::move(ptt).value();
    runner->set_ptt(ptt_->active());
  }
  return runner;
}

std::unique_ptr<AntennaBackend> StationDaemon::make_guarded(std::unique_ptr<AntennaBackend> inner) {
  std::string latch = config_.gpio.estop_latch_file;
  if (latch.empty()) {
    latch = (std::filesystem::path(options_.config_path).parent_path() / "estop.latched").string();
  }
  auto guarded = std::make_unique<GuardedAntenna>(
      std::move(inner), config_.gpio,
      GuardParts{gpio_.get(), sequencer_.get(), latch, [this] { return now_s(); },
                 [this] { modes_.stop(); },
                 [](const std::string& line) { spdlog::warn("{}", line); }, off_loop()});
  // WSJT-X transmitting, or the motors' supply off or still settling.
  guarded->set_other_hold([this] {
    return (radio_ && radio_->motion_hold()) || (power_ && power_->motion_hold(now_s()));
  });
  guard_ = guarded.get();
  return guarded;
}

std::string StationDaemon::beside_config(const std::string& path) const {
  const std::filesystem::path p(path);
  return p.is_absolute() ? p.string()
                         : (std::filesystem::path(options_.config_path).parent_path() / p).string();
}

double StationDaemon::mount_az() const {
  const auto p = antenna_->position(now_s());
  return p ? p->az_mount_deg : config_.start_mount().az_deg;
}

Offload StationDaemon::off_loop() {
  return [this](std::function<void()> work, std::function<void()> done) {
    worker_.post(std::move(work), std::move(done));
  };
}

double StationDaemon::now_s() const {
  return std::chrono::duration<double>(SteadyClock::now() - start_).count();
}

void StationDaemon::start_target() {
  start_waits_for_elements_ = false;
  if (config_.start_target == "stop" || guard_->estop_latched()) return;
  const TargetRequest request = target_from_name(config_.start_target);
  const auto outcome =
      commands_.point(CommandSource{CommandSource::Kind::Configuration, "configuration"}, request);
  if (outcome.accepted() || outcome.refusal->status != proto::ServiceStatus::Invalid) return;
  // A satellite may be missing or too old only until the sources' first download (a first start
  // has no cache): the daemon runs and follows it once fresh elements are published.
  if (std::holds_alternative<SatelliteTarget>(request)) {
    start_waits_for_elements_ = true;
    spdlog::warn("[target].name: {}; it is followed once the element sets hold it",
                 outcome.refusal->reason);
    return;
  }
  // A name the station does not know is a mistake in the file; a latched fault is "not now".
  throw UsageError("[target].name: " + outcome.refusal->reason);
}

void StationDaemon::open_servers() {
  const auto limits = config_.target_limits();
  if (config_.rotctld.port != 0) {
    auto server = linux_os::TcpProtocolServer::open(
        io_, "rotctld", config_.rotctld.bind, config_.rotctld.port,
        [this, limits](const std::string& client) {
          return proto::make_rotctld_session(service_, client, limits);
        },
        [this](const std::string& client, const std::string& event) {
          log_.info("rotctld", client + " " + event, now_s());
        },
        linux_os::TcpServerLimits{.idle_timeout_s = config_.rotctld_idle_timeout_s});
    if (!server) throw UsageError("[rotctld]: " + server.error().message);
    spdlog::info("rotctld protocol on {}:{} (rotctl -m 2 -r {}:{})", config_.rotctld.bind,
                 server.value()->port(), config_.rotctld.bind, server.value()->port());
    rotctld_ = std::move(server).value();
  }
  for (std::size_t i = 0; i < config_.serial.size(); ++i) {
    const SerialServerConfig& c = config_.serial[i];
    auto server = linux_os::SerialProtocolServer::open(
        io_, c.device, c.baud, [this, c, limits] { return serial_session(c, service_, limits); },
        [this, c](const std::string& event) {
          log_.info(c.device, std::string(c.protocol_name()) + " " + c.device + ": " + event,
                    now_s());
        });
    if (!server) {
      throw UsageError("[[serial]] #" + std::to_string(i + 1) + " (" +
                       std::string(c.protocol_name()) + "): " + server.error().message);
    }
    spdlog::info("{} on {}", c.protocol_name(), server.value()->path());
    serial_.push_back(std::move(server).value());
  }
  if (config_.pstrotator.port != 0) {
    auto server = linux_os::UdpDatagramServer::open(
        io_, "pstrotator", config_.pstrotator.bind, config_.pstrotator.port,
        config_.pstrotator_reply_port,
        [this, limits](std::string_view datagram, const std::string& client) {
          return proto::handle_pstrotator_datagram(datagram, service_, client, limits);
        });
    if (!server) throw UsageError("[pstrotator]: " + server.error().message);
    server.value()->on_oversized([this](std::size_t bytes, const std::string& client) {
      log_.info(client,
                client + ": a datagram of " + std::to_string(bytes) +
                    " bytes is over the limit and was dropped whole",
                now_s());
    });
    spdlog::info("PstRotator UDP on {}:{} (replies to port {})", config_.pstrotator.bind,
                 server.value()->port(), config_.pstrotator_reply_port);
    pstrotator_ = std::move(server).value();
  }
  if (config_.web.port != 0) open_console();
}

void StationDaemon::open_console() {
  nlohmann::json servers = nlohmann::json::object();
  if (rotctld_) {
    servers["rotctld"] = config_.rotctld.bind + ":" + std::to_string(rotctld_->port());
  }
  console_ = std::make_unique<ConsoleServer>(
      io_,
      ConsoleParts{config_,
                   store_,
                   *ephemeris_,
                   sky_,
                   modes_,
                   commands_,
                   *antenna_,
                   &satellites_,
                   [this] { return now_s(); },
                   [this] { return unix_now_s(); },
                   servers,
                   [this] {
                     nlohmann::json io = guard_->state();
                     // The tick that began the hold, on the daemon's UTC (WSJT-X's transmit
                     // hold measured against the datagram: tests/integration/radio_test.py).
                     const auto held = guard_->held_since_s();
                     io["held_since_unix_s"] = held ? nlohmann::json(unix_now_s() - now_s() + *held)
                                                    : nlohmann::json(nullptr);
                     io["sequencer"] = sequencer_->state();
                     io["motor_power"] = power_ ? power_->to_json(now_s()) : nlohmann::json();
                     io["gamepad"] = pad_ ? pad_->to_json() : nlohmann::json();
                     return io;
                   },
                   off_loop(),
                   &events_,
                   &motions_,
                   [](const std::string& line) { spdlog::warn("{}", line); },
                   [this] { return gps_->to_json(); },
                   clock_.get(),
                   [this] { return network_->to_json(); },
                   [this] { return receiver_->to_json(); },
                   scanner_.get(),
                   [this](const std::string& who) { restart_soon(who); },
                   &direction_test_,
                   radio_ ? std::function<nlohmann::json()>([this] { return radio_->radio_json(); })
                          : nullptr,
                   radio_ ? std::function<nlohmann::json()>([this] { return radio_->wsjtx_json(); })
                          : nullptr,
                   elements_.get(),
                   schedule_.get(),
                   noise_.get(),
                   recorder_.get(),
                   beside_config(kRecordingsDir),
                   beside_config(kNoiseLogFile),
                   calibration_.get(),
                   &pointing_history_,
                   pol_.get()},
      [](const std::string& line) { spdlog::warn("{}", line); },
      SoftwareUpdates::Config{std::string(program_version()), std::string(package_architecture()),
                              options_.update_inbox, options_.update_status});
  spdlog::info("web console on http://{}:{}/", config_.web.bind, console_->port());
}

void StationDaemon::control_event(const std::string& text) {
  const std::string line = log_safe(text);
  log_.info("control " + line.substr(0, line.find(": ")), line, now_s());
  events_.add(unix_now_s(), line);
}

void StationDaemon::motion_event(const CommandSource& source, const CommandRecord& record) {
  start_waits_for_elements_ = false;  // someone chose: the start target no longer applies
  if (schedule_) schedule_->on_command(source);
  const std::string line = log_safe(source.name + ": " + record.words);
  log_.info("motion " + source.name, line, now_s());
  direction_test_.interrupt(source.name + ": " + record.words);
  // A program's stream of positions is one entry; a new target or a STOP is a new one.
  motions_.add(
      unix_now_s(), line,
      source.name + "|" + (record.stream_kind.empty() ? record.words : record.stream_kind));
}

}  // namespace azt::app
