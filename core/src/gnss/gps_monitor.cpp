#include "azt/gnss/gps_monitor.hpp"

namespace azt::gnss {

std::string_view to_string(GpsState s) {
  switch (s) {
    case GpsState::Off:
      return "off";
    case GpsState::NoGpsd:
      return "no_gpsd";
    case GpsState::NoFix:
      return "no_fix";
    case GpsState::Fix2d:
      return "fix2d";
    case GpsState::Fix3d:
      return "fix3d";
  }
  return "off";
}

void GpsMonitor::on_connected(double /*now_s*/) { connected_ = true; }

void GpsMonitor::on_disconnected(double /*now_s*/) {
  connected_ = false;
  fix_.reset();
  fix_at_s_.reset();
  sky_.reset();
  sky_at_s_.reset();
  time_unix_s_.reset();
}

void GpsMonitor::on_fix(double now_s, const GpsFix& fix) {
  fix_ = fix;
  fix_at_s_ = now_s;
  if (fix.time_unix_s) time_unix_s_ = fix.time_unix_s;
}

void GpsMonitor::on_sky(double now_s, const GpsSky& sky) {
  sky_ = sky;
  sky_at_s_ = now_s;
}

bool GpsMonitor::fresh(const std::optional<double>& at_s, double now_s) const {
  return at_s && now_s - *at_s <= settings_.stale_after_s;
}

GpsStatus GpsMonitor::status(double now_s) const {
  GpsStatus s;
  if (!settings_.enabled) return s;
  if (!connected_) {
    s.state = GpsState::NoGpsd;
    return s;
  }
  s.state = GpsState::NoFix;
  if (fresh(sky_at_s_, now_s)) {
    s.sats_used = sky_->sats_used;
    s.sats_visible = sky_->sats_visible;
    s.hdop = sky_->hdop;
    s.satellites = sky_->satellites;
  }
  s.time_unix_s = time_unix_s_;
  if (!fresh(fix_at_s_, now_s) || fix_->mode == FixMode::None) return s;
  s.state = fix_->mode == FixMode::Fix3d ? GpsState::Fix3d : GpsState::Fix2d;
  s.lat_deg = fix_->lat_deg;
  s.lon_deg = fix_->lon_deg;
  if (fix_->mode == FixMode::Fix3d) s.alt_m = fix_->alt_m;
  return s;
}

}  // namespace azt::gnss
