// The satellite station's parts (docs/satellites.md): the element sets from their sources, the
// tracker's settings, the schedule's follower and the motors' power relay it switches.
#include <spdlog/spdlog.h>
#include <sys/resource.h>
#include <unistd.h>

#include "azt/linux/http_download.hpp"
#include "common/horizon_mask_option.hpp"
#include "common/program_version.hpp"
#include "common/usage_error.hpp"
#include "daemon/station_daemon.hpp"

namespace azt::app {

std::unique_ptr<ElementFeed> StationDaemon::make_element_feed() {
  const SatellitesConfig& c = config_.satellites;
  ElementFeedSettings settings;
  if (!c.file.empty()) settings.file = beside_config(c.file);
  settings.sources = c.sources;
  settings.refresh_s = c.refresh_h * 3600.0;
  settings.cache_path = beside_config("elements-cache.json");
  linux_os::DownloadOptions download;
  download.ca_file = c.ca_file.empty() ? "" : beside_config(c.ca_file);
  download.proxy = c.proxy;
  download.max_redirects = c.max_redirects;
  download.connect_timeout_s = c.connect_timeout_s;
  download.total_timeout_s = c.timeout_s;
  download.max_bytes = static_cast<std::size_t>(c.max_mb * 1e6);
  download.user_agent = "azeltrack/" + std::string(program_version());
  download.cancel = &downloads_cancelled_;
  // The downloads' TLS and the parsing of megabytes compete with the control loop for two cores:
  // their thread yields (nice 10, setpriority(2) on the thread's own id, which Linux allows).
  download_worker_.post(
      [] { (void)::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 10); }, [] {});
  return std::make_unique<ElementFeed>(ElementFeedParts{
      settings, [download](const std::string& url) { return linux_os::download(url, download); },
      [this](std::function<void()> work, std::function<void()> done) {
        download_worker_.post(std::move(work), std::move(done));
      },
      off_loop(), [this] { return unix_now_s(); },
      [this](SatelliteCatalogue catalogue, double unix_s) {
        satellites_.adopt(std::move(catalogue), unix_s);
        if (schedule_) schedule_->catalogue_changed();
        if (start_waits_for_elements_) start_target();
      },
      [](const std::string& line) { spdlog::info("{}", line); }});
}

SatelliteSettings StationDaemon::satellite_settings() const {
  SatelliteSettings s;
  s.age = orbit::ElementAgeLimits{config_.satellites.stale_days, config_.satellites.refuse_days};
  s.mask = parse_horizon_mask("[satellites] mask", config_.satellites.mask);
  s.dut1_s = config_.sky.settings.dut1_s;
  s.site = config_.sky.settings.observer;
  s.mount = track::mount_geometry(config_.station);  // the mount's, not the plant's
  s.mount.loss_error_deg = config_.satellites.beamwidth_deg / 2.0;
  return s;
}

std::unique_ptr<MotorPower> StationDaemon::make_motor_power() {
  const auto& c = config_.hardware.power;
  if (!c) return nullptr;
  std::unique_ptr<linux_os::GpioOutput> relay;
  if (c->simulated()) {
    relay = simulated_output(c->relay);
  } else {
    auto line = gpio_->output(c->relay, true);  // powered from the start
    if (!line) throw UsageError(line.error().message);
    relay = std::move(line.value());
  }
  return std::make_unique<MotorPower>(std::move(relay), c->on_lead_s,
                                      [](const std::string& line) { spdlog::info("{}", line); });
}

ScheduleSite StationDaemon::schedule_site() const {
  return ScheduleSite{config_.sky.settings.observer, config_.sky.settings.dut1_s,
                      parse_horizon_mask("[satellites] mask", config_.satellites.mask)};
}

std::unique_ptr<ScheduleFollower> StationDaemon::make_schedule() {
  return std::make_unique<ScheduleFollower>(
      ScheduleFollowerParts{
          commands_, satellites_, power_.get(), off_loop(), [this] { return unix_now_s(); },
          [this] { return now_s(); },
          [this] {
            const auto p = antenna_->position(now_s());
            return p ? control::AzEl{p->az_deg, p->el_deg} : config_.park[0].position;
          },
          [this] {
            const auto p = antenna_->position(now_s());
            return p && !p->moving;
          },
          [this](ScheduleEvent event, const schedule::Priority* sat, const PlannedPass* pass) {
            schedule_event(event, sat, pass);
          },
          [](const std::string& line) { spdlog::info("{}", line); }},
      config_.schedule, schedule_site(), schedule_rules_of(config_));
}

void StationDaemon::schedule_event(ScheduleEvent event, const schedule::Priority* sat,
                                   const PlannedPass* pass) {
  std::string line = "schedule: " + std::string(to_string(event));
  if (sat != nullptr) line += " " + sat->sat + " (" + sat->norad + ")";
  events_.add(unix_now_s(), line);
  (void)pass;
}

}  // namespace azt::app
