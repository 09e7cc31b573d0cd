// The console's views of the running station: /api/state, /api/config, /api/targets, /api/sky
// (DaemonConsole's read side; its actions are in daemon_console.cpp and console_settings.cpp).
#include "console/daemon_console.hpp"

#include <cmath>

#include "azt/astro/bands.hpp"
#include "azt/astro/time_scales.hpp"
#include "common/sky_report.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

std::string kind_name(astro::Target::Kind kind) {
  switch (kind) {
    case astro::Target::Kind::Sun:
      return "sun";
    case astro::Target::Kind::Moon:
      return "moon";
    case astro::Target::Kind::Source:
      return "source";
    case astro::Target::Kind::RaDec:
      return "radec";
    case astro::Target::Kind::Spacecraft:
      return "spacecraft";
  }
  return "radec";
}

/// One target of the console's list, where it is now: a spacecraft outside its table is listed
/// without a position and with the reason; the others go on.
json target_entry(const astro::Target& target, const Result<astro::TargetReport>& r) {
  json t{{"name", target.name}, {"kind", kind_name(target.kind)}};
  if (target.kind == astro::Target::Kind::Spacecraft) {
    t["description"] = target.description;
    t["frequency_mhz"] = target.frequency_mhz;
  }
  if (!r) {
    t["az_deg"] = nullptr;
    t["el_deg"] = nullptr;
    t["error"] = r.error().message;
    return t;
  }
  t["az_deg"] = r->observation.place.az_deg;
  t["el_deg"] = r->observation.el_deg;
  if (target.kind == astro::Target::Kind::Spacecraft) {
    t["range_km"] = r->observation.place.distance_km.value_or(0.0);
    t["range_rate_km_s"] = r->observation.place.range_rate_km_s.value_or(0.0);
  }
  return t;
}

}  // namespace

json DaemonConsole::moon_json(const astro::TargetReport& r, const astro::SkySnapshot& sky) const {
  const SkyConfig& station = p_.config.sky;
  const json full = report_json(r, sky, station.settings, p_.ephemeris.name());
  json doppler = json::object();
  for (const auto& b : full["bands"]) doppler[b["band"].get<std::string>()] = b["echo_doppler_hz"];
  const auto field = [&full](const char* name) { return full.value(name, json(nullptr)); };
  json dx = nullptr;  // the Moon seen from the DX station, as WSJT-X's Astro window shows it
  if (full.contains("dx")) {
    dx = {{"az_deg", full["dx"]["az_deg"]},
          {"el_deg", full["dx"]["el_geometric_deg"]},
          {"dec_deg", full["dx"]["dec_deg"]}};
  }
  return {{"az_deg", r.observation.place.az_deg},
          {"el_deg", r.observation.el_deg},
          {"dec_deg", r.observation.place.dec_deg},
          {"distance_km", full["distance_km"]},
          {"echo_delay_s", field("echo_delay_s")},
          {"band", station.band_name},
          {"echo_doppler_hz", field("echo_doppler_hz")},
          {"echo_doppler_rate_hz_min", field("echo_doppler_rate_hz_min")},
          {"dx_echo_doppler_hz", field("dx_echo_doppler_hz")},
          {"dx_echo_doppler_rate_hz_min", field("dx_echo_doppler_rate_hz_min")},
          {"dx", dx},
          {"doppler_hz", doppler},
          // WSJT-X's Astronomical Data, at the band (docs/eme.md).
          {"parallactic_deg", field("parallactic_deg")},
          {"dpol_deg", field("dpol_deg")},
          {"self_dpol_deg", field("self_dpol_deg")},
          {"dx_dpol_deg", field("dx_dpol_deg")},
          {"mnr_db", field("mnr_db")},
          {"tsky_k", field("tsky_k")},
          {"dgrd_db", field("dgrd_db")},
          {"sun_sep_deg", field("sun_sep_deg")},
          {"illumination", field("illumination")},
          {"width_hz", field("width_hz")},
          {"dx_width_hz", field("dx_width_hz")}};
}

const DaemonConsole::Snapshot& DaemonConsole::snapshot() {
  const double now = std::floor(p_.unix_s());
  if (now == snapshot_.unix_s) return snapshot_;
  Snapshot s;
  s.unix_s = now;
  const SkyConfig& station = p_.config.sky;
  const auto sky =
      sky_snapshot(p_.ephemeris, station.settings, astro::UtcInstant::from_unix_seconds(now));
  // Outside the ephemeris: the sky part of the state stays empty, the rest is still served.
  for (const auto& target : sky ? station.targets : std::vector<astro::Target>{}) {
    const auto r = sky->observe(target);
    s.targets.push_back(target_entry(target, r));
    if (r && target.kind == astro::Target::Kind::Moon) s.moon = moon_json(*r, *sky);
    if (r && target.kind == astro::Target::Kind::Sun) {
      s.sun = {{"az_deg", r->observation.place.az_deg}, {"el_deg", r->observation.el_deg}};
    }
  }
  snapshot_ = std::move(s);
  return snapshot_;
}

json DaemonConsole::target_json() {
  const control::Mode mode = p_.modes.mode();
  if (p_.commands.tracking_satellite()) {
    const json s = p_.satellites->status(p_.unix_s());
    return {{"name", p_.modes.who()},
            {"az_deg", s.value("aim_az_deg", json(nullptr))},
            {"el_deg", s.value("aim_el_deg", json(nullptr))},
            {"satellite", s}};
  }
  if (mode == control::Mode::Track && p_.sky.target()) {
    const auto fix = p_.sky.at(p_.unix_s());
    return {{"name", p_.sky.target()->name},
            {"az_deg", fix ? json(fix->position.az_deg) : json(nullptr)},
            {"el_deg", fix ? json(fix->position.el_deg) : json(nullptr)},
            {"waiting", fix ? wait_.waiting(p_.sky.target(), fix->position.el_deg, p_.unix_s())
                            : json(nullptr)}};
  }
  if (const auto fixed = p_.modes.fixed_target()) {
    return {{"name", p_.modes.who()}, {"az_deg", fixed->az_deg}, {"el_deg", fixed->el_deg}};
  }
  return {{"name", nullptr}, {"az_deg", nullptr}, {"el_deg", nullptr}};
}

json DaemonConsole::control_json() const {
  const ControlHolder c = p_.commands.control();
  return {{"holder", c.holder},
          {"by", c.by},
          {"since", c.since_unix_s > 0.0 ? json(astro::format_iso8601_utc_unix(c.since_unix_s))
                                         : json(nullptr)},
          {"pc_allowed", c.pc_allowed}};
}

json DaemonConsole::state() {
  const double mono = p_.monotonic_s();
  const auto here = p_.antenna.position(mono);
  json antenna{{"known", here.has_value()}};
  if (here) {
    antenna.update({{"az_deg", here->az_deg},
                    {"el_deg", here->el_deg},
                    {"az_mount_deg", here->az_mount_deg},
                    {"moving", here->moving}});
  }
  if (const auto raw = p_.antenna.encoder_reading()) {
    antenna["encoder_az_deg"] = raw->az_deg;
    antenna["encoder_el_deg"] = raw->el_deg;
  }
  if (json axes = axes_json(); !axes.empty()) antenna["axes"] = std::move(axes);
  json target = target_json();
  if (const auto& fixed = p_.config.mount.el_fixed) {
    // A fixed-elevation array: its elevation is known, not read, and a target counts when it
    // is inside the array's vertical beam (docs/eme.md "Fixed-elevation arrays").
    antenna["el_fixed_deg"] = fixed->el_deg;
    if (target["el_deg"].is_number())
      target["in_beam"] = fixed->in_beam(target["el_deg"].get<double>());
  }
  json error = nullptr;
  // While the target is below the horizon limit the antenna holds: no error to show.
  const bool waiting = target.contains("waiting") && !target["waiting"].is_null();
  if (here && !waiting && target["az_deg"].is_number() && target["el_deg"].is_number()) {
    error = {{"az", std::remainder(target["az_deg"].get<double>() - here->az_deg, 360.0)},
             {"el", target["el_deg"].get<double>() - here->el_deg}};
  }
  const Snapshot& sky = snapshot();
  const auto& c = p_.config.station.corrections;
  const auto& obs = p_.config.sky.settings.observer;
  return {{"utc", astro::format_iso8601_utc_unix(p_.unix_s())},
          {"mode", std::string(control::to_string(p_.modes.mode()))},
          {"who", p_.commands.commander()},
          {"pc_locked_out", p_.modes.external_locked()},
          {"control", control_json()},
          {"antenna", antenna},
          {"target", target},
          {"error_deg", error},
          {"moon", sky.moon.is_null() ? json(nullptr) : sky.moon},
          {"sun", sky.sun.is_null() ? json(nullptr) : sky.sun},
          {"corrections",
           {{"az_user_deg", c.user.az_deg()},
            {"el_user_deg", c.user.el_deg()},
            {"az_offset_deg", c.offsets.az_deg},
            {"el_offset_deg", c.offsets.el_deg}}},
          {"station",
           {{"grid", p_.config.sky.settings.grid},
            {"lat_deg", obs.lat_deg},
            {"lon_deg", obs.lon_deg},
            {"alt_m", obs.height_m}}},
          {"time", p_.clock != nullptr ? p_.clock->to_json() : json(nullptr)},
          {"network", p_.network ? p_.network() : json(nullptr)},
          {"gps", p_.gps ? p_.gps() : json{{"state", "off"}}},
          {"receiver", p_.receiver ? p_.receiver() : json{{"source", "none"}, {"state", "off"}}},
          {"scan", p_.scanner ? p_.scanner->to_json() : json{{"state", "idle"}}},
          {"noise", p_.noise ? p_.noise->to_json() : json{{"state", "idle"}}},
          {"recording", p_.recorder ? p_.recorder->to_json() : json{{"state", "idle"}}},
          {"calibration", calibration_json()},
          {"faults", p_.antenna.faults()},
          {"pol", pol_json()},
          {"events", p_.events != nullptr ? p_.events->to_json() : json::array()},
          {"commands", p_.motions != nullptr ? p_.motions->to_json() : json::array()},
          {"station_io", p_.station_io ? p_.station_io() : json(nullptr)},
          {"radio", p_.radio ? p_.radio() : json{{"doppler", "off"}, {"link", "off"}}},
          {"schedule", p_.schedule != nullptr ? p_.schedule->state() : json(nullptr)},
          {"wsjtx", p_.wsjtx ? p_.wsjtx() : json{{"listening", false}}},
          {"satellites", satellites_json()},
          {"servers", p_.servers}};
}

json DaemonConsole::satellites_json() const {
  // Where the elements come from and how each source last went (docs/satellites.md): a failed
  // source shows its reason while its previous sets stay in use.
  return {{"count", p_.satellites != nullptr ? p_.satellites->catalogue().satellites().size() : 0},
          {"fetching", p_.elements != nullptr && p_.elements->fetching()},
          {"sources", p_.elements != nullptr ? p_.elements->to_json() : json::array()}};
}

json DaemonConsole::config() {
  const DaemonConfig& c = p_.config;
  const auto& corr = c.station.corrections;
  const auto& obs = c.sky.settings.observer;
  json park = json::array();
  for (std::size_t i = 0; i < p_.modes.park_slots().size(); ++i) {
    const auto& slot = p_.modes.park_slots()[i];
    park.push_back({{"slot", i + 1},
                    {"name", slot.name},
                    {"az_deg", slot.position.az_deg},
                    {"el_deg", slot.position.el_deg}});
  }
  json serial = json::array();
  for (const auto& s : c.serial) {
    serial.push_back({{"protocol", s.protocol_name()}, {"device", s.device}, {"baud", s.baud}});
  }
  return {
      {"station",
       {{"grid", c.sky.settings.grid},
        {"lat_deg", obs.lat_deg},
        {"lon_deg", obs.lon_deg},
        {"alt_m", obs.height_m}}},
      {"band", c.sky.band_name},
      {"dx_grid", c.sky.settings.dx_grid},
      {"control",
       {{"window_deg", c.station.az_control.window_deg},
        {"ramp_s", c.station.az_control.ramp_s},
        {"tracking_speed", c.station.az_control.tracking_speed}}},
      {"geometry",
       {{"az_min_deg", c.station.az_range.min_deg},
        {"az_max_deg", c.station.az_range.max_deg},
        {"el_min_deg", c.station.el_range.min_deg},
        {"el_max_deg", c.station.el_range.max_deg}}},
      {"corrections",
       {{"az_offset_deg", corr.offsets.az_deg},
        {"el_offset_deg", corr.offsets.el_deg},
        {"az_user_deg", corr.user.az_deg()},
        {"el_user_deg", corr.user.el_deg()},
        {"tilt_el_deg", corr.tilt.entries_deg()}}},
      {"park", park},
      {"servers",
       {{"rotctld", {{"bind", c.rotctld.bind}, {"port", c.rotctld.port}}},
        {"pstrotator", {{"bind", c.pstrotator.bind}, {"port", c.pstrotator.port}}},
        {"serial", serial},
        {"web", {{"bind", c.web.bind}, {"port", c.web.port}}}}},
      {"restart_needed", restart_needed_},
  };
}

json DaemonConsole::targets() {
  json bands = json::array();
  for (const auto& b : astro::eme_bands()) {
    bands.push_back({{"band", std::string(b.name)},
                     {"freq_mhz", b.freq_mhz},
                     {"wavelength", std::string(b.wavelength)}});
  }
  return {
      {"targets", snapshot().targets},
      {"satellites", p_.satellites != nullptr ? p_.satellites->list(p_.unix_s()) : json::array()},
      {"park", config()["park"]},
      {"bands", bands}};
}

json DaemonConsole::sky(double hours) {
  json out{{"now", snapshot().targets}};
  const SkyConfig& station = p_.config.sky;
  json moon_path = json::array();
  json sun_path = json::array();
  const double start = std::floor(p_.unix_s() / 600.0) * 600.0;
  const auto steps = static_cast<int>(std::floor(hours * 6.0));  // every 10 minutes
  for (int i = 0; i <= steps; ++i) {
    const double t = start + 600.0 * i;
    const auto snap =
        sky_snapshot(p_.ephemeris, station.settings, astro::UtcInstant::from_unix_seconds(t));
    const auto moon = snap ? snap->observe(astro::Target::moon()) : snap.error();
    const auto sun = snap ? snap->observe(astro::Target::sun()) : snap.error();
    if (!moon || !sun) break;  // past the ephemeris or the leap-second table
    moon_path.push_back({{"utc", astro::format_iso8601_utc_unix(t)},
                         {"az_deg", moon->observation.place.az_deg},
                         {"el_deg", moon->observation.el_deg}});
    sun_path.push_back({{"utc", astro::format_iso8601_utc_unix(t)},
                        {"az_deg", sun->observation.place.az_deg},
                        {"el_deg", sun->observation.el_deg}});
  }
  out["moon_path"] = moon_path;
  out["sun_path"] = sun_path;
  out["pass_path"] = p_.commands.tracking_satellite() ? p_.satellites->pass_track() : json::array();
  return out;
}

}  // namespace azt::app
