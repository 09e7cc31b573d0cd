#include "station/clock_watch.hpp"

#include <memory>
#include <utility>

#include "azt/timekeeping/ntp_servers.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

json optional_json(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json source_json(const timekeeping::ChronySource& s) {
  return {{"name", s.name},
          {"mode", std::string(timekeeping::mode_name(s.mode))},
          {"state", std::string(timekeeping::state_name(s.state))},
          {"stratum", s.stratum},
          {"poll_s", s.poll_log2_s >= 0 ? double(1 << s.poll_log2_s) : 1.0 / (1 << -s.poll_log2_s)},
          {"reach", s.reach},
          {"last_rx_s", optional_json(s.last_rx_s)},
          {"offset_s", s.offset_s},
          {"error_s", s.error_s}};
}

json tracking_json(const timekeeping::ChronyTracking& t) {
  return {{"stratum", t.stratum},
          {"ref", t.ref_name},
          {"ref_id", t.ref_id_hex},
          {"offset_s", t.system_offset_s},
          {"last_offset_s", t.last_offset_s},
          {"rms_offset_s", t.rms_offset_s},
          {"frequency_ppm", t.frequency_ppm},
          {"root_delay_s", t.root_delay_s},
          {"root_dispersion_s", t.root_dispersion_s},
          {"update_interval_s", t.update_interval_s},
          {"leap", t.leap}};
}

}  // namespace

ClockWatch::ClockWatch(boost::asio::io_context& io, ClockWatchParts parts)
    : p_(std::move(parts)),
      looks_(
          io, p_.config.poll_s, p_.offload,
          [probe = p_.probe, read = p_.read_servers, managed = p_.config.manage_chrony] {
            return Look{probe(), managed ? read() : std::vector<std::string>{}};
          },
          [this](Look look) { on_look(std::move(look)); }) {
  looks_.start();
}

double ClockWatch::stale_after_s() const {
  // Three missed looks, plus the time one may take (chronyc is killed after 5 s).
  constexpr double kProbeTimeoutS = 5.0;
  return 3.0 * p_.config.poll_s + kProbeTimeoutS;
}

void ClockWatch::check_now() { looks_.now(); }

void ClockWatch::on_look(Look look) {
  look.reading.read_at_s = p_.monotonic_s();
  latest_ = std::move(look.reading);
  servers_ = std::move(look.servers);
  const auto status = timekeeping::assess_clock(latest_, p_.monotonic_s(), stale_after_s());
  if (logged_reason_ == status.reason) return;
  logged_reason_ = status.reason;
  if (status.synced) {
    const std::string ref = latest_->tracking ? latest_->tracking->ref_name : "the kernel's clock";
    p_.log("time: the clock is synchronised (" + ref + ")");
  } else {
    p_.log("time: the clock is not synchronised: " + status.reason + " (tracking carries on)");
  }
}

json ClockWatch::to_json() const {
  const auto status = timekeeping::assess_clock(latest_, p_.monotonic_s(), stale_after_s());
  json j{{"synced", status.synced},
         {"chrony_synced", status.chrony_synced},
         {"reason", status.reason.empty() ? json(nullptr) : json(status.reason)},
         {"kernel_synced", nullptr},
         {"rtc", latest_ && latest_->rtc_present},
         {"chrony_error", nullptr},
         {"stratum", nullptr},
         {"ref", nullptr},
         {"offset_s", nullptr},
         {"root_dispersion_s", nullptr},
         {"sources", json::array()},
         {"managed", p_.config.manage_chrony},
         {"servers", p_.config.manage_chrony ? json(servers_) : json(nullptr)},
         {"sources_file", p_.config.manage_chrony ? json(p_.config.sources_file) : json(nullptr)},
         {"checked_s_ago", latest_ ? json(p_.monotonic_s() - latest_->read_at_s) : json(nullptr)}};
  if (!latest_) return j;
  if (latest_->kernel_synced) j["kernel_synced"] = *latest_->kernel_synced;
  if (!latest_->chrony_error.empty()) j["chrony_error"] = latest_->chrony_error;
  if (latest_->tracking) j.update(tracking_json(*latest_->tracking));
  for (const auto& s : latest_->sources) j["sources"].push_back(source_json(s));
  return j;
}

void ClockWatch::set_servers(const std::vector<std::string>& servers,
                             std::function<void(Result<bool>)> done) {
  if (!p_.config.manage_chrony) {
    done(fail("[time] manage_chrony is off: chrony's own configuration names the servers"));
    return;
  }
  auto checked = timekeeping::check_ntp_servers(servers);
  if (!checked) {
    done(checked.error());
    return;
  }
  auto outcome = std::make_shared<Result<bool>>(fail("the write did not finish"));
  p_.offload(
      [outcome, apply = p_.apply_servers, names = checked.value()] { *outcome = apply(names); },
      [this, outcome, names = checked.value(), done = std::move(done)] {
        if (*outcome) {
          std::string list;
          for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
          p_.log("time: chrony's NTP servers set: " + (list.empty() ? "none" : list));
          servers_ = names;
          check_now();
        }
        done(*outcome);
      });
}

}  // namespace azt::app
