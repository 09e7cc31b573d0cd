#include "daemon/daemon.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <vector>

#include <filesystem>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_io.hpp"
#include "azt/linux/asio.hpp"
#include "azt/linux/crash_safe_outputs.hpp"
#include "azt/linux/libgpiod_lines.hpp"
#include "azt/linux/serial_protocol_server.hpp"
#include "azt/linux/systemd_notify.hpp"
#include "azt/linux/tcp_protocol_server.hpp"
#include "azt/linux/udp_datagram_server.hpp"
#include "azt/linux/worker_thread.hpp"
#include "azt/proto/pstrotator.hpp"
#include "azt/proto/sessions.hpp"
#include "azt/sim/pass_sim.hpp"
#include "azt/util/valid_utf8.hpp"
#include "common/horizon_mask_option.hpp"
#include "common/sky_setup.hpp"
#include "common/target_request.hpp"
#include "common/usage_error.hpp"
#include "console/console_server.hpp"
#include "daemon/tick_stats.hpp"
#include "station/guarded_antenna.hpp"
#include "station/recent_events.hpp"
#include "station/satellite_tracker.hpp"
#include "station/sequencer_runner.hpp"
#include "station/sky_follower.hpp"
#include "station/station_commands.hpp"
#include "station/station_service.hpp"

namespace azt::app {
namespace {

namespace asio = boost::asio;
using SteadyClock = std::chrono::steady_clock;

double unix_now_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

/// At most `burst` lines per key per minute; the rest are counted and summarised, so a client
/// reconnecting in a loop cannot flood the journal.
class RateLimitedLog {
 public:
  void info(const std::string& key, const std::string& line, double now_s) {
    auto& b = buckets_[key];
    if (now_s - b.window_start_s > 60.0) {
      if (b.suppressed > 0) spdlog::info("{}: {} similar messages suppressed", key, b.suppressed);
      b = Bucket{now_s, 0, 0};
    }
    if (++b.sent <= kBurst) {
      spdlog::info("{}", line);
    } else {
      ++b.suppressed;
    }
  }

 private:
  static constexpr int kBurst = 10;
  struct Bucket {
    double window_start_s = -1e9;
    int sent = 0;
    int suppressed = 0;
  };
  std::map<std::string, Bucket> buckets_;
};

/// A client's bytes may be in a log line: valid UTF-8, no control characters, a bounded length.
std::string log_safe(const std::string& text) {
  std::string line = valid_utf8(text.substr(0, 240));
  std::replace_if(
      line.begin(), line.end(), [](char c) { return c >= 0 && c < ' '; }, ' ');
  return line;
}

std::unique_ptr<proto::ProtocolSession> serial_session(const SerialServerConfig& c,
                                                       proto::RotatorService& service,
                                                       const proto::TargetLimits& limits) {
  const std::string client = c.protocol + " " + c.device;
  if (c.protocol == "gs232a" || c.protocol == "gs232b") {
    return proto::make_gs232_session(
        service, client, c.protocol == "gs232a" ? proto::Gs232Variant::A : proto::Gs232Variant::B,
        limits);
  }
  if (c.protocol == "easycomm1" || c.protocol == "easycomm2") {
    return proto::make_easycomm_session(
        service, client,
        c.protocol == "easycomm1" ? proto::EasyCommVersion::One : proto::EasyCommVersion::Two,
        limits);
  }
  proto::SpidConfig spid;
  spid.dialect =
      c.protocol == "rot1prog" ? proto::SpidDialect::Rot1Prog : proto::SpidDialect::Rot2Prog;
  return proto::make_spid_session(service, client, spid);
}

class Daemon {
 public:
  Daemon(ConfigStore& store, const DaemonOptions& options)
      : config_(store.config()),
        store_(store),
        options_(options),
        start_(SteadyClock::now()),
        ephemeris_(open_ephemeris(config_.sim.station.sky.ephemeris)),
        sky_(*ephemeris_, config_.sim.station),
        modes_(config_.park, config_.out_of_range, config_.sim.setup.el_range.min_deg),
        gpio_(config_.gpio.any_line() || config_.hardware.uses_gpio()
                  ? linux_os::make_libgpiod_provider(io_)
                  : nullptr),
        sequencer_(make_sequencer()),
        antenna_(make_guarded(make_backend())),
        satellites_(satellite_settings(),
                    [](const std::string& line) { spdlog::info("{}", line); }),
        commands_(StationCommandParts{modes_, *antenna_, sky_, &satellites_,
                                      config_.target_limits(), config_.sim.setup.el_range,
                                      [this] { return now_s(); }, [] { return unix_now_s(); },
                                      config_.sim.setup.az_plant.start_deg,
                                      [this](const CommandSource& source, const std::string& what) {
                                        motion_event(source, what);
                                      },
                                      [this](const CommandSource& source, const Refusal& refusal) {
                                        control_event(source.name + ": refused: " + refusal.reason);
                                      }}),
        service_(
            commands_, modes_, *antenna_, [this] { return now_s(); },
            "azeltrack " AZT_VERSION " " + antenna_->describe() + " at " +
                config_.sim.station.sky.grid,
            [this](const std::string& line) { control_event(line); }),
        // SIGHUP too: a closed terminal must stop the motors, not kill the process mid-move.
        signals_(io_, SIGINT, SIGTERM, SIGHUP),
        timer_(io_),
        period_(std::chrono::duration_cast<SteadyClock::duration>(
            std::chrono::duration<double>(config_.sim.setup.tick_s))) {}

  std::unique_ptr<AntennaBackend> make_backend() {
    if (config_.backend == "hamlib") return make_hamlib_backend(config_);
    if (config_.backend == "pwm") return make_pwm_backend(io_, config_);
    if (config_.backend == "hardware") {
      return make_hardware_backend(io_, config_, HardwarePorts::linux_devices(gpio_.get()));
    }
    return make_sim_backend(config_);
  }

  std::unique_ptr<SequencerRunner> make_sequencer() {
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

  std::unique_ptr<AntennaBackend> make_guarded(std::unique_ptr<AntennaBackend> inner) {
    std::string latch = config_.gpio.estop_latch_file;
    if (latch.empty()) {
      latch =
          (std::filesystem::path(options_.config_path).parent_path() / "estop.latched").string();
    }
    auto guarded = std::make_unique<GuardedAntenna>(
        std::move(inner), config_.gpio,
        GuardParts{gpio_.get(), sequencer_.get(), latch, [this] { return now_s(); },
                   [this] { modes_.stop(); },
                   [](const std::string& line) { spdlog::warn("{}", line); }, off_loop()});
    guard_ = guarded.get();
    return guarded;
  }

  SatelliteSettings satellite_settings() const {
    SatelliteSettings s;
    if (!config_.satellites.file.empty()) {
      const std::filesystem::path file(config_.satellites.file);
      s.file = file.is_absolute()
                   ? file.string()
                   : (std::filesystem::path(options_.config_path).parent_path() / file).string();
    }
    s.mask = parse_horizon_mask("[satellites] mask", config_.satellites.mask);
    s.dut1_s = config_.sim.station.sky.dut1_s;
    s.site = config_.sim.station.sky.observer;
    s.mount = sim::mount_geometry(config_.sim.setup);
    return s;
  }

  /// Where the mount's azimuth is (for choosing a pass's wrap side), or the configured start.
  double mount_az() const {
    const auto p = antenna_->position(now_s());
    return p ? p->az_mount_deg : config_.sim.setup.az_plant.start_deg;
  }

  int run() {
    linux_os::install_crash_handlers();
    satellites_.poll_file(unix_now_s());  // at once: the start target may be a satellite
    satellites_.set_offload(off_loop());
    start_target();
    open_servers();
    signals_.async_wait([this](boost::system::error_code ec, int signal) {
      if (!ec) {
        shutdown(signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "SIGHUP");
      }
    });
    if (options_.run_for_s > 0.0) {
      auto stop_timer = std::make_shared<asio::steady_timer>(io_);
      stop_timer->expires_after(std::chrono::duration_cast<SteadyClock::duration>(
          std::chrono::duration<double>(options_.run_for_s)));
      stop_timer->async_wait([this, stop_timer](boost::system::error_code ec) {
        if (!ec) shutdown("--run-for elapsed");
      });
    }
    deadline_ = SteadyClock::now() + period_;
    arm_tick();
    spdlog::info("serving {} with {}; tick {:.0f} Hz", options_.config_path, antenna_->describe(),
                 1.0 / config_.sim.setup.tick_s);
    notifier_.ready("tracking " + modes_.who());
    if (options_.on_loop_started) asio::post(io_, [this] { options_.on_loop_started(io_); });
    try {
      io_.run();
    } catch (const std::exception& e) {
      fail_safe(std::string("internal error: ") + e.what());
      return kExitFailure;
    } catch (...) {
      fail_safe("internal error (not a std::exception)");
      return kExitFailure;
    }
    spdlog::info("stopped; tick {}", stats_.summary());
    return 0;
  }

 private:
  /// What may block goes to the worker; its result comes back to the loop (off_loop.hpp).
  Offload off_loop() {
    return [this](std::function<void()> work, std::function<void()> done) {
      worker_.post(std::move(work), std::move(done));
    };
  }

  double now_s() const {
    return std::chrono::duration<double>(SteadyClock::now() - start_).count();
  }

  void start_target() {
    if (config_.start_target == "stop" || guard_->estop_latched()) return;
    const auto outcome =
        commands_.point(CommandSource{CommandSource::Kind::Configuration, "configuration"},
                        target_from_name(config_.start_target));
    // A name the station does not know is a mistake in the file; a latched fault is "not now".
    if (!outcome.accepted() && outcome.refusal->status == proto::ServiceStatus::Invalid) {
      throw UsageError("[target].name: " + outcome.refusal->reason);
    }
  }

  void open_servers() {
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
            log_.info(c.device, c.protocol + " " + c.device + ": " + event, now_s());
          });
      if (!server) {
        throw UsageError("[[serial]] #" + std::to_string(i + 1) + " (" + c.protocol +
                         "): " + server.error().message);
      }
      spdlog::info("{} on {}", c.protocol, server.value()->path());
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
      spdlog::info("PstRotator UDP on {}:{} (replies to port {})", config_.pstrotator.bind,
                   server.value()->port(), config_.pstrotator_reply_port);
      pstrotator_ = std::move(server).value();
    }
    if (config_.web.port != 0) open_console();
  }

  void open_console() {
    nlohmann::json servers = nlohmann::json::object();
    if (rotctld_) {
      servers["rotctld"] = config_.rotctld.bind + ":" + std::to_string(rotctld_->port());
    }
    console_ = std::make_unique<ConsoleServer>(
        io_,
        ConsoleParts{config_, store_, *ephemeris_, sky_, modes_, commands_, *antenna_, &satellites_,
                     [this] { return now_s(); }, [] { return unix_now_s(); }, servers,
                     [this] {
                       nlohmann::json io = guard_->state();
                       io["sequencer"] = sequencer_->state();
                       return io;
                     },
                     off_loop(), &events_, &motions_,
                     [](const std::string& line) { spdlog::warn("{}", line); }},
        [](const std::string& line) { spdlog::warn("{}", line); });
    spdlog::info("web console on http://{}:{}/", config_.web.bind, console_->port());
  }

  void arm_tick() {
    timer_.expires_at(deadline_);
    timer_.async_wait([this](boost::system::error_code ec) {
      if (ec || stopping_) return;
      const auto woke = SteadyClock::now();
      stats_.add(std::chrono::duration<double>(woke - deadline_).count());
      tick();
      // Absolute deadlines: a late tick does not delay the next one. After a stall longer than
      // a period (suspend, debugger) skip ahead instead of running a burst of ticks.
      deadline_ += period_;
      if (SteadyClock::now() > deadline_) {
        stats_.overrun();
        deadline_ = SteadyClock::now() + period_;
      }
      arm_tick();
    });
  }

  void tick() {
    const double now = now_s();
    modes_.update(now);
    satellites_.poll_file(unix_now_s());
    satellites_.refresh_passes(unix_now_s());
    if (commands_.tracking_satellite()) {
      control::AzEl rate;
      const control::Demand demand = satellites_.demand(unix_now_s(), mount_az(), rate);
      antenna_->tick(now, demand, rate);
    } else {
      std::optional<SkyFix> fix;
      if (modes_.mode() == control::Mode::Track) {
        fix = sky_.at(unix_now_s());
      }
      const control::Demand demand =
          modes_.demand(fix ? std::optional(fix->position) : std::nullopt);
      antenna_->tick(now, demand, fix ? fix->rate_deg_s : control::AzEl{});
    }
    report_faults();
    // Mode changes by PC programs and new faults reach open consoles at once.
    std::string summary = std::string(control::to_string(modes_.mode())) + " " + modes_.who() +
                          " " + std::to_string(last_faults_.size());
    if (summary != last_summary_) {
      last_summary_ = std::move(summary);
      if (console_) console_->push_now();
    }
    notifier_.watchdog();
  }

  /// A refusal a client was given: in the journal (at most 10 lines a minute per client) and in
  /// the console's recent events.
  void control_event(const std::string& text) {
    const std::string line = log_safe(text);
    log_.info("control " + line.substr(0, line.find(": ")), line, now_s());
    events_.add(unix_now_s(), line);
  }

  /// An accepted motion command: in the journal (at most 10 lines a minute per source, the rest
  /// counted) and in the console's recent commands, one line per source and kind of command.
  void motion_event(const CommandSource& source, const std::string& what) {
    const std::string line = log_safe(source.name + ": " + what);
    log_.info("motion " + source.name, line, now_s());
    // A program's stream of positions is one entry; a new target or a STOP is a new one.
    const bool stream = what.rfind("position ", 0) == 0 || what.rfind("continuous ", 0) == 0;
    motions_.add(unix_now_s(), line,
                 source.name + "|" + (stream ? what.substr(0, what.find(' ')) : what));
  }

  void report_faults() {
    const auto faults = antenna_->faults();
    if (faults != last_faults_) {
      for (const auto& f : faults) spdlog::warn("fault: {}", f);
      if (faults.empty() && !last_faults_.empty()) spdlog::info("faults cleared");
      last_faults_ = faults;
    }
  }

  /// An exception escaped a handler: the loop's state is unknown, so the station goes safe and
  /// the process exits (systemd restarts it, motionless until a client asks).
  void fail_safe(const std::string& why) {
    stopping_ = true;
    antenna_->stop_now(now_s());
    sequencer_->release_now();
    spdlog::critical("{}: motors stopped, transmitter released, exiting", why);
    notifier_.stopping();
  }

  void shutdown(const std::string& why) {
    if (stopping_) return;
    stopping_ = true;
    notifier_.stopping();
    // Motors first, then the servers: nothing may move after this line.
    antenna_->stop_now(now_s());
    sequencer_->release_now();
    spdlog::info("{}: motors stopped, shutting down", why);
    if (rotctld_) rotctld_->close();
    for (auto& s : serial_) s->close();
    if (pstrotator_) pstrotator_->close();
    if (console_) console_->close();
    boost::system::error_code ignored;
    timer_.cancel();
    signals_.cancel(ignored);
    io_.stop();
  }

  DaemonConfig config_;  ///< the running configuration; the console changes parts of it
  ConfigStore& store_;
  DaemonOptions options_;
  SteadyClock::time_point start_;
  asio::io_context io_;
  /// Password checks, configuration saves, the E-stop latch file: what may block, off the loop.
  /// Its jobs' work halves touch only what they captured, and their done halves run only on the
  /// loop, so it may outlive the parts they report to (it is joined after them).
  linux_os::WorkerThread worker_{io_};
  std::unique_ptr<astro::Ephemeris> ephemeris_;
  SkyFollower sky_;
  control::ModeController modes_;
  std::unique_ptr<linux_os::GpioProvider> gpio_;
  std::unique_ptr<linux_os::GpioInput> ptt_;
  std::unique_ptr<SequencerRunner> sequencer_;
  GuardedAntenna* guard_ = nullptr;
  std::unique_ptr<AntennaBackend> antenna_;
  SatelliteTracker satellites_;
  RateLimitedLog log_;
  RecentEvents events_;
  RecentEvents motions_;  ///< accepted motion commands, with their sources
  StationCommands commands_;
  StationService service_;
  asio::signal_set signals_;
  asio::steady_timer timer_;
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
};

}  // namespace

int run_daemon(ConfigStore& store, const DaemonOptions& options) {
  Daemon daemon(store, options);
  return daemon.run();
}

}  // namespace azt::app
