#include "station/gps_receiver.hpp"

#include <cmath>
#include <utility>

#include "azt/astro/time_scales.hpp"
#include "azt/gnss/fix_range.hpp"

namespace azt::app {
namespace {

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json site_json(const gnss::Site& s) {
  return {{"lat_deg", s.lat_deg}, {"lon_deg", s.lon_deg}, {"alt_m", s.alt_m}};
}

}  // namespace

GpsReceiver::GpsReceiver(boost::asio::io_context& io, GpsReceiverParts parts)
    : p_(std::move(parts)), monitor_({p_.config.enabled, 3.0}), survey_(p_.config.survey) {
  if (!p_.config.enabled) return;
  linux_os::GpsdEvents events{
      [this] {
        monitor_.on_connected(p_.monotonic_s());
        p_.log("gps: connected to gpsd at " + p_.config.host + ":" + p_.config.port);
      },
      [this](const std::string& why) {
        monitor_.on_disconnected(p_.monotonic_s());
        p_.log("gps: no gpsd: " + why);
      },
      [this](const gnss::GpsFix& fix) { on_fix(fix); },
      [this](const gnss::GpsSky& sky) { monitor_.on_sky(p_.monotonic_s(), sky); }};
  client_ = std::make_unique<linux_os::GpsdClient>(
      io, linux_os::GpsdClientConfig{p_.config.host, p_.config.port, 2.0}, std::move(events));
}

gnss::GpsFix GpsReceiver::screened(const gnss::GpsFix& reported) {
  const auto why = gnss::out_of_range(reported);
  if (!why) {
    refusing_ = false;
    return reported;
  }
  ++fixes_refused_;
  last_fix_refused_ = *why;
  if (!refusing_)
    p_.log("gps: a fix off the Earth refused (" + *why + "); no fix until a good one");
  refusing_ = true;
  gnss::GpsFix none = reported;
  none.mode = gnss::FixMode::None;  // shown as no fix; the survey restarts
  return none;
}

void GpsReceiver::on_fix(const gnss::GpsFix& reported) {
  const double now = p_.monotonic_s();
  const gnss::GpsFix fix = screened(reported);
  monitor_.on_fix(now, fix);
  // The survey runs on the receiver's own clock: a fix a second whatever the daemon's load, and
  // a replayed log surveys the same whatever its playback speed. A fix without time breaks it.
  survey_.on_fix(fix.time_unix_s.value_or(-1e9), fix, monitor_.status(now).sats_used);
  if (p_.config.use_position) offer_survey();
}

void GpsReceiver::offer_survey() {
  const auto site = survey_.surveyed();
  if (!site || adopting_) return;
  switch (gnss::decide_site(in_use_, *site, p_.tracking(), p_.config.survey.jump_m)) {
    case gnss::SiteDecision::Keep:
      return;
    case gnss::SiteDecision::Jump:
      if (!refused_ || gnss::ground_distance_m(*refused_, *site) > p_.config.survey.jump_m) {
        p_.log("gps: the fix moved " +
               std::to_string(std::lround(gnss::ground_distance_m(*in_use_, *site))) +
               " m while tracking: position not changed (stop tracking to adopt it)");
      }
      refused_ = site;
      return;
    case gnss::SiteDecision::Adopt:
      break;
  }
  adopting_ = true;
  p_.adopt(*site, [this, site = *site](bool ok) {
    adopting_ = false;
    if (!ok) return;
    in_use_ = site;
    refused_.reset();
  });
}

nlohmann::json GpsReceiver::to_json() const {
  const gnss::GpsStatus s = monitor_.status(p_.monotonic_s());
  nlohmann::json sats = nlohmann::json::array();
  for (const auto& sat : s.satellites) {
    sats.push_back({{"prn", sat.prn},
                    {"el_deg", sat.el_deg},
                    {"az_deg", sat.az_deg},
                    {"snr_dbhz", sat.snr_dbhz},
                    {"used", sat.used}});
  }
  return {
      {"state", std::string(gnss::to_string(s.state))},
      {"lat_deg", optional_json(s.lat_deg)},
      {"lon_deg", optional_json(s.lon_deg)},
      {"alt_m", optional_json(s.alt_m)},
      {"sats_used", s.sats_used},
      {"sats_visible", s.sats_visible},
      {"hdop", optional_json(s.hdop)},
      {"time_utc",
       s.time_unix_s ? nlohmann::json(astro::format_iso8601_utc_unix(*s.time_unix_s)) : nullptr},
      {"position_in_use", in_use_.has_value()},
      {"surveyed", in_use_ ? site_json(*in_use_) : nlohmann::json(nullptr)},
      {"jump_refused", refused_ ? site_json(*refused_) : nlohmann::json(nullptr)},
      {"fixes_refused", fixes_refused_},
      {"last_fix_refused", last_fix_refused_},
      {"satellites", sats}};
}

}  // namespace azt::app
