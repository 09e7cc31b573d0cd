#include "console/daemon_console.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>

#include "azt/astro/bands.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/calibration/scan_plan.hpp"
#include "azt/timekeeping/ntp_servers.hpp"
#include "common/sky_report.hpp"
#include "common/usage_error.hpp"
#include "config/sky_config.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

double number(const json& body, const std::string& key) {
  const auto it = body.find(key);
  if (it == body.end()) throw ApiError(400, key, key + " is required");
  if (!it->is_number()) throw ApiError(400, key, key + " must be a number");
  const double v = it->get<double>();
  if (!std::isfinite(v)) throw ApiError(400, key, key + " must be finite");
  return v;
}

std::optional<double> optional_number(const json& body, const std::string& key) {
  if (!body.contains(key)) return std::nullopt;
  return number(body, key);
}

/// An integer field in [lo, hi], checked before it is narrowed: 4294967297 is refused, never
/// taken for 1 (issue 12 row 9). nlohmann keeps large positives as unsigned, so both are read.
std::int64_t whole_number(const json& body, const std::string& key, std::int64_t lo,
                          std::int64_t hi, const std::string& message) {
  const auto it = body.find(key);
  if (it == body.end()) throw ApiError(400, key, message);
  if (it->is_number_unsigned()) {
    const auto v = it->get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(hi) || static_cast<std::int64_t>(v) < lo) {
      throw ApiError(400, key, message);
    }
    return static_cast<std::int64_t>(v);
  }
  if (!it->is_number_integer()) throw ApiError(400, key, message);
  const auto v = it->get<std::int64_t>();
  if (v < lo || v > hi) throw ApiError(400, key, message);
  return v;
}

std::string text(const json& body, const std::string& key) {
  const auto it = body.find(key);
  if (it == body.end() || !it->is_string()) throw ApiError(400, key, key + " must be a string");
  return it->get<std::string>();
}

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

std::string utc_text(double unix_s) {
  return astro::format_iso8601_utc(astro::UtcInstant::from_unix_seconds(unix_s));
}

toml::table& table_at(toml::table& root, const char* name) {
  if (!root.contains(name)) root.insert(name, toml::table{});
  toml::table* t = root[name].as_table();
  if (t == nullptr) throw ApiError(400, name, std::string("[") + name + "] is not a table");
  return *t;
}

}  // namespace

namespace {

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
  return {{"az_deg", r.observation.place.az_deg},
          {"el_deg", r.observation.el_deg},
          {"distance_km", full["distance_km"]},
          {"echo_delay_s", full.value("echo_delay_s", json(nullptr))},
          {"band", station.band_name},
          {"echo_doppler_hz", full.value("echo_doppler_hz", json(nullptr))},
          {"dx_echo_doppler_hz", full.value("dx_echo_doppler_hz", json(nullptr))},
          {"doppler_hz", doppler},
          // Issue 16 §1: WSJT-X's Astronomical Data, at the band (docs/eme.md).
          {"parallactic_deg", full.value("parallactic_deg", json(nullptr))},
          {"dpol_deg", full.value("dpol_deg", json(nullptr))},
          {"dx_dpol_deg", full.value("dx_dpol_deg", json(nullptr))},
          {"mnr_db", full.value("mnr_db", json(nullptr))},
          {"tsky_k", full.value("tsky_k", json(nullptr))},
          {"dgrd_db", full.value("dgrd_db", json(nullptr))},
          {"sun_sep_deg", full.value("sun_sep_deg", json(nullptr))},
          {"illumination", full.value("illumination", json(nullptr))},
          {"width_hz", full.value("width_hz", json(nullptr))},
          {"dx_width_hz", full.value("dx_width_hz", json(nullptr))}};
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
          {"since", c.since_unix_s > 0.0 ? json(utc_text(c.since_unix_s)) : json(nullptr)},
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
  json target = target_json();
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
  return {{"utc", utc_text(p_.unix_s())},
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
          {"faults", p_.antenna.faults()},
          {"events", p_.events != nullptr ? p_.events->to_json() : json::array()},
          {"commands", p_.motions != nullptr ? p_.motions->to_json() : json::array()},
          {"station_io", p_.station_io ? p_.station_io() : json(nullptr)},
          {"servers", p_.servers}};
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
    moon_path.push_back({{"utc", utc_text(t)},
                         {"az_deg", moon->observation.place.az_deg},
                         {"el_deg", moon->observation.el_deg}});
    sun_path.push_back({{"utc", utc_text(t)},
                        {"az_deg", sun->observation.place.az_deg},
                        {"el_deg", sun->observation.el_deg}});
  }
  out["moon_path"] = moon_path;
  out["sun_path"] = sun_path;
  out["pass_path"] = p_.commands.tracking_satellite() ? p_.satellites->pass_track() : json::array();
  return out;
}

void DaemonConsole::save(const std::string& field, ConfigStore::Change change,
                         std::function<json()> apply, ActDone done) {
  // The store and the running station change only back on the loop, in the order the saves
  // were asked for.
  p_.store.save_off_loop(
      p_.offload, std::move(change),
      [this, field, apply = std::move(apply),
       done = std::move(done)](Result<std::vector<std::string>> notices) {
        if (!notices) {
          done(ActResult{json::object(), save_refusal(field, notices.error().message)});
          return;
        }
        for (const auto& notice : notices.value()) p_.log(notice);
        done(ActResult{apply(), std::nullopt});
      });
}

ApiError DaemonConsole::save_refusal(const std::string& field, std::string message) const {
  // "config FILE: line N: [station].grid …" -> "[station].grid …": the page shows it by the field.
  const std::string prefix = "config " + p_.store.path() + ": ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  if (message.rfind("line ", 0) == 0 && message.find(": ") != std::string::npos) {
    message.erase(0, message.find(": ") + 2);
  }
  // Another program holding the file is "not now", not a bad value.
  const bool busy = message.find("is held by another program") != std::string::npos;
  return ApiError(busy ? 503 : 400, field, message);
}

void DaemonConsole::apply_corrections(const control::PositionCorrections& corrections) {
  p_.config.station.corrections = corrections;
  p_.antenna.set_corrections(corrections);
}

void DaemonConsole::act(const std::string& action, const json& body, const std::string& source,
                        ActDone done) {
  if (action == "target") {
    done(ActResult{act_target(body, source), std::nullopt});
    return;
  }
  if (action == "stop") {
    p_.commands.stop(CommandSource{CommandSource::Kind::Console, source});
    done(ActResult{});
    return;
  }
  if (action == "control/pc") {
    const auto outcome = p_.commands.allow_pc(CommandSource{CommandSource::Kind::Console, source});
    done(ActResult{{{"mode", outcome.mode}, {"control", control_json()}}, std::nullopt});
    return;
  }
  if (action == "scan") {
    done(ActResult{act_scan(body, source), std::nullopt});
    return;
  }
  if (action == "scan/stop") {
    if (p_.scanner != nullptr) p_.scanner->stop("stopped by " + source);
    done(ActResult{p_.scanner != nullptr ? p_.scanner->to_json() : json{{"state", "idle"}},
                   std::nullopt});
    return;
  }
  if (action == "faults/clear") {
    p_.antenna.clear_faults();
    p_.log(source + ": latched faults cleared");
    done(ActResult{});
    return;
  }
  using Act = void (DaemonConsole::*)(const json&, ActDone);
  static const std::map<std::string, Act, std::less<>> save_actions = {
      {"correction", &DaemonConsole::act_correction},
      {"config/station", &DaemonConsole::act_station},
      {"config/band", &DaemonConsole::act_band},
      {"config/dx", &DaemonConsole::act_dx},
      {"config/offsets", &DaemonConsole::act_offsets},
      {"scan/apply", &DaemonConsole::act_scan_apply},
      {"config/tilt", &DaemonConsole::act_tilt},
      {"config/park", &DaemonConsole::act_park},
      {"config/control", &DaemonConsole::act_control},
      {"time/servers", &DaemonConsole::act_time_servers}};
  const auto it = save_actions.find(action);
  if (it == save_actions.end()) throw ApiError(404, "", "no such action: " + action);
  (this->*(it->second))(body, std::move(done));
}

void DaemonConsole::act_time_servers(const json& body, ActDone done) {
  if (p_.clock == nullptr) throw ApiError(503, "servers", "the clock is not watched here");
  if (!body.contains("servers") || !body["servers"].is_array()) {
    throw ApiError(400, "servers", "servers must be a list of host names or addresses");
  }
  std::vector<std::string> servers;
  for (const auto& s : body["servers"]) {
    if (!s.is_string()) throw ApiError(400, "servers", "each server must be a string");
    servers.push_back(s.get<std::string>());
  }
  if (const auto checked = timekeeping::check_ntp_servers(servers); !checked) {
    throw ApiError(400, "servers", checked.error().message);
  }
  p_.clock->set_servers(servers, [this, done = std::move(done)](const Result<bool>& r) {
    if (!r) {
      // Not managed here is "not now"; a file or chronyd that failed is the station's trouble.
      const bool off = r.error().message.find("manage_chrony is off") != std::string::npos;
      done(ActResult{{}, ApiError(off ? 409 : 503, "servers", r.error().message)});
      return;
    }
    done(ActResult{{{"time", p_.clock->to_json()}}, std::nullopt});
  });
}

TargetRequest DaemonConsole::target_request(const json& body) {
  if (body.contains("name")) return target_from_name(text(body, "name"));
  if (body.contains("ra_deg") || body.contains("dec_deg")) {
    return RaDecTarget{number(body, "ra_deg"), number(body, "dec_deg")};
  }
  if (body.contains("park")) {
    return ParkTarget{whole_number(body, "park", 1, 4, "park must be a slot number 1 to 4")};
  }
  if (body.contains("az_deg") || body.contains("el_deg")) {
    return PositionTarget{number(body, "az_deg"), number(body, "el_deg")};
  }
  throw ApiError(400, "name", "expected name, ra_deg/dec_deg, park or az_deg/el_deg");
}

/// The scan's settings from the request, checked before anything moves (the plan's own
/// refusals name their field first: "beamwidth_deg must be …").
std::pair<calibration::ScanSpec, calibration::ScanTiming> scan_settings(const json& body) {
  calibration::ScanSpec spec;
  if (body.contains("kind")) {
    auto kind = calibration::parse_scan_kind(text(body, "kind"));
    if (!kind) throw ApiError(400, "kind", kind.error().message);
    spec.kind = *kind;
  }
  spec.beamwidth_deg = number(body, "beamwidth_deg");
  if (body.contains("points_per_line")) {
    spec.points_per_line = static_cast<std::size_t>(
        whole_number(body, "points_per_line", 5, 101, "points_per_line must be odd, 5 to 101"));
  }
  spec.half_span_beams = optional_number(body, "half_span_beams").value_or(spec.half_span_beams);
  spec.reference_beams = optional_number(body, "reference_beams").value_or(spec.reference_beams);
  calibration::ScanTiming timing;
  timing.settle_s = optional_number(body, "settle_s").value_or(timing.settle_s);
  timing.dwell_s = optional_number(body, "dwell_s").value_or(timing.dwell_s);
  if (!(timing.settle_s >= 0.0 && timing.settle_s <= 60.0)) {
    throw ApiError(400, "settle_s", "settle_s must be 0 to 60");
  }
  if (!(timing.dwell_s > 0.0 && timing.dwell_s <= 60.0)) {
    throw ApiError(400, "dwell_s", "dwell_s must be above 0 and at most 60");
  }
  if (auto plan = calibration::plan_scan(spec); !plan) {
    const std::string& why = plan.error().message;
    throw ApiError(400, why.substr(0, why.find(' ')), why);
  }
  return {spec, timing};
}

json DaemonConsole::act_scan(const json& body, const std::string& source) {
  if (p_.scanner == nullptr) throw ApiError(503, "", "no pointing scans here");
  const auto [spec, timing] = scan_settings(body);
  const std::string name = text(body, "source");
  if (auto ready = p_.scanner->ready(p_.monotonic_s()); !ready) {
    throw ApiError(503, "", ready.error().message);
  }
  json pointed = act_target(json{{"name", name}}, source);  // tracks the source, or refuses
  if (!p_.sky.target()) throw ApiError(400, "source", "a scan needs a sky source");
  auto started = p_.scanner->start(p_.sky.target()->name, spec, timing, p_.monotonic_s());
  if (!started) throw ApiError(503, "", started.error().message);
  p_.log(source + ": pointing scan of " + p_.sky.target()->name);
  pointed["scan"] = p_.scanner->to_json();
  return pointed;
}

void DaemonConsole::act_scan_apply(const json& /*body*/, ActDone done) {
  if (p_.scanner == nullptr || !p_.scanner->found()) {
    throw ApiError(409, "", "no scan result to apply: run a scan to its end first");
  }
  if (scan_apply_pending_) throw ApiError(409, "", "the scan result is being applied already");
  const ScanOffsets found = *p_.scanner->found();
  // The beam was on the source where the readings said source + found: take it off the value in
  // the file now, not this process's copy, which `azeltrack config set` may have changed since
  // (issue 27 §9). The result stays applicable until the save is done: a save refused while
  // another program holds the file must not lose minutes of scanning (§8).
  scan_apply_pending_ = true;
  save(
      "az_offset_deg",
      [found](toml::table& root) {
        toml::table& t = table_at(root, "corrections");
        const double az = t["az_offset_deg"].value_or(0.0) - found.az_offset_deg;
        const double el = t["el_offset_deg"].value_or(0.0) - found.el_offset_deg;
        if (auto ok = control::AxisOffsets::make(az, el); !ok) {
          throw UsageError("the offsets would go out of range: " + ok.error().message);
        }
        t.insert_or_assign("az_offset_deg", az);
        t.insert_or_assign("el_offset_deg", el);
      },
      [this, found] {
        if (const auto now = p_.scanner->found(); now &&
                                                  now->az_offset_deg == found.az_offset_deg &&
                                                  now->el_offset_deg == found.el_offset_deg) {
          p_.scanner->applied();  // not a newer scan's result, which finished meanwhile
        }
        apply_corrections(p_.store.config().station.corrections);
        return json::object();
      },
      [this, done = std::move(done)](ActResult result) {
        scan_apply_pending_ = false;
        done(std::move(result));
      });
}

json DaemonConsole::act_target(const json& body, const std::string& source) {
  const CommandOutcome outcome =
      p_.commands.point(CommandSource{CommandSource::Kind::Console, source}, target_request(body));
  if (const auto& r = outcome.refusal) {
    // The same refusal a PC program gets, as HTTP: a bad value, "not now", or no position.
    const unsigned status = r->status == proto::ServiceStatus::Rejected      ? 409
                            : r->status == proto::ServiceStatus::Unavailable ? 503
                                                                             : 400;
    throw ApiError(status, r->field, r->reason);
  }
  return {{"mode", outcome.mode}, {"target", outcome.target}};
}

void DaemonConsole::act_correction(const json& body, ActDone done) {
  const bool reset = body.value("reset", false);
  std::string axis;
  std::int32_t steps = 0;
  if (!reset) {
    axis = text(body, "axis");
    if (axis != "az" && axis != "el") throw ApiError(400, "axis", "axis must be \"az\" or \"el\"");
    steps = static_cast<std::int32_t>(
        whole_number(body, "steps", -1000, 1000,
                     "steps must be an integer number of 0.01° steps, |steps| ≤ 1000"));
  }
  // The nudge applies to the value in the file now, and only that axis is written: a value set
  // meanwhile by `azeltrack config set` is never overwritten from this process's memory.
  save(
      reset ? "corrections" : "steps",
      [reset, axis, steps](toml::table& root) {
        toml::table& t = table_at(root, "corrections");
        if (reset) {
          t.insert_or_assign("az_user_deg", 0.0);
          t.insert_or_assign("el_user_deg", 0.0);
          return;
        }
        auto c = control::UserCorrections::from_deg(t["az_user_deg"].value_or(0.0),
                                                    t["el_user_deg"].value_or(0.0));
        if (!c) throw UsageError("[corrections]: " + c.error().message);
        control::UserCorrections user = c.value();
        const bool whole = axis == "az" ? user.nudge_az(steps) : user.nudge_el(steps);
        if (!whole) throw UsageError("the correction is at its ±10.00° limit");
        t.insert_or_assign(axis + "_user_deg", axis == "az" ? user.az_deg() : user.el_deg());
      },
      [this] {
        const auto& c = p_.store.config().station.corrections;
        apply_corrections(c);
        return json{{"az_user_deg", c.user.az_deg()}, {"el_user_deg", c.user.el_deg()}};
      },
      std::move(done));
}

void DaemonConsole::act_station(const json& body, ActDone done) {
  ConfigStore::Change change;
  if (body.contains("grid")) {
    change = [grid = text(body, "grid")](toml::table& root) {
      toml::table& s = table_at(root, "station");
      s.insert_or_assign("grid", grid);
      s.erase("lat_deg");  // the locator's centre becomes the position
      s.erase("lon_deg");
    };
  } else {
    const double lat = number(body, "lat_deg");
    const double lon = number(body, "lon_deg");
    const auto alt = optional_number(body, "alt_m");
    change = [lat, lon, alt](toml::table& root) {
      set_station_position(table_at(root, "station"), lat, lon, alt);
    };
  }
  save(
      body.contains("grid") ? "grid" : "lat_deg", std::move(change),
      [this] {
        p_.config.sky = p_.store.config().sky;
        p_.sky.refollow();
        if (p_.satellites != nullptr) p_.satellites->set_site(p_.config.sky.settings.observer);
        snapshot_.unix_s = -1.0;
        return json{{"station", config()["station"]}};
      },
      std::move(done));
}

void DaemonConsole::act_band(const json& body, ActDone done) {
  save(
      "band",
      [band = text(body, "band")](toml::table& root) {
        table_at(root, "sky").insert_or_assign("band", band);
      },
      [this] {
        p_.config.sky.band_name = p_.store.config().sky.band_name;
        p_.config.sky.settings.freq_mhz = p_.store.config().sky.settings.freq_mhz;
        snapshot_.unix_s = -1.0;
        return json{{"band", p_.config.sky.band_name}};
      },
      std::move(done));
}

void DaemonConsole::act_dx(const json& body, ActDone done) {
  save(
      "dx_grid",
      [dx = text(body, "dx_grid")](toml::table& root) {
        toml::table& sky = table_at(root, "sky");
        if (dx.empty()) {
          sky.erase("dx_grid");
        } else {
          sky.insert_or_assign("dx_grid", dx);
        }
      },
      [this] {
        p_.config.sky.settings.dx = p_.store.config().sky.settings.dx;
        p_.config.sky.settings.dx_grid = p_.store.config().sky.settings.dx_grid;
        snapshot_.unix_s = -1.0;
        return json{{"dx_grid", p_.config.sky.settings.dx_grid}};
      },
      std::move(done));
}

void DaemonConsole::act_offsets(const json& body, ActDone done) {
  const auto az = optional_number(body, "az_offset_deg");
  const auto el = optional_number(body, "el_offset_deg");
  if (!az && !el) throw ApiError(400, "az_offset_deg", "give az_offset_deg and/or el_offset_deg");
  save(
      az ? "az_offset_deg" : "el_offset_deg",
      [az, el](toml::table& root) {
        toml::table& t = table_at(root, "corrections");
        if (az) t.insert_or_assign("az_offset_deg", *az);
        if (el) t.insert_or_assign("el_offset_deg", *el);
      },
      [this] {
        apply_corrections(p_.store.config().station.corrections);
        return json::object();
      },
      std::move(done));
}

void DaemonConsole::act_tilt(const json& body, ActDone done) {
  constexpr std::size_t kEntries = control::TiltTable::kEntries;
  std::optional<std::vector<double>> whole;
  std::size_t index = 0;
  double value = 0.0;
  if (body.contains("tilt_el_deg")) {
    const auto& a = body["tilt_el_deg"];
    if (!a.is_array() || a.size() != kEntries) {
      throw ApiError(400, "tilt_el_deg", "tilt_el_deg must be an array of 60 numbers");
    }
    whole.emplace();
    for (const auto& e : a) {
      if (!e.is_number()) throw ApiError(400, "tilt_el_deg", "tilt_el_deg must hold numbers");
      whole->push_back(e.get<double>());
    }
  } else {
    index = static_cast<std::size_t>(
        whole_number(body, "index", 0, kEntries - 1, "index must be 0 to 59"));
    value = number(body, "value");
  }
  // One entry changes one entry of the table in the file now, not the table in memory.
  save(
      "tilt_el_deg",
      [whole, index, value](toml::table& root) {
        toml::table& t = table_at(root, "corrections");
        toml::array a;
        if (whole) {
          for (const double e : *whole) a.push_back(e);
        } else {
          if (const toml::array* old = t["tilt_el_deg"].as_array()) a = *old;
          if (a.empty()) {
            for (std::size_t i = 0; i < kEntries; ++i) a.push_back(0.0);
          }
          if (index >= a.size())
            throw UsageError("[corrections] tilt_el_deg has no entry " + std::to_string(index));
          a.replace(a.cbegin() + static_cast<std::ptrdiff_t>(index), value);
        }
        t.insert_or_assign("tilt_el_deg", a);
      },
      [this] {
        apply_corrections(p_.store.config().station.corrections);
        return json::object();
      },
      std::move(done));
}

void DaemonConsole::act_park(const json& body, ActDone done) {
  const auto slot =
      static_cast<std::size_t>(whole_number(body, "slot", 1, 4, "slot must be 1 to 4"));
  std::optional<std::string> name;
  if (body.contains("name")) name = text(body, "name");
  const auto az = optional_number(body, "az_deg");
  const auto el = optional_number(body, "el_deg");
  // Only this slot's given keys change in the file; slots missing before it are written with
  // what the station runs with, so the file's numbering stays the console's.
  save(
      az ? "az_deg" : "el_deg",
      [slot, name, az, el, running = p_.modes.park_slots()](toml::table& root) {
        toml::array a;
        if (const toml::array* old = root["park"].as_array()) a = *old;
        while (a.size() < slot) {
          const control::ParkSlot& s = running[a.size()];
          a.push_back(toml::table{
              {"name", s.name}, {"az_deg", s.position.az_deg}, {"el_deg", s.position.el_deg}});
        }
        toml::table* item = a.get(slot - 1)->as_table();
        if (item == nullptr) throw UsageError("park." + std::to_string(slot) + " is not a table");
        if (name) item->insert_or_assign("name", *name);
        if (az) item->insert_or_assign("az_deg", *az);
        if (el) item->insert_or_assign("el_deg", *el);
        root.insert_or_assign("park", a);
      },
      [this] {
        p_.config.park = p_.store.config().park;
        p_.modes.set_park_slots(p_.config.park);
        return json::object();
      },
      std::move(done));
}

void DaemonConsole::act_control(const json& body, ActDone done) {
  std::vector<std::string> keys;
  for (const char* key : {"window_deg", "ramp_s", "tracking_speed"}) {
    if (body.contains(key)) keys.emplace_back(key);
  }
  if (keys.empty()) throw ApiError(400, "window_deg", "give window_deg, ramp_s or tracking_speed");
  std::vector<double> values;
  values.reserve(keys.size());
  for (const auto& k : keys) values.push_back(number(body, k));
  save(
      keys.front(),
      [keys, values](toml::table& root) {
        toml::table& t = table_at(root, "control");
        for (std::size_t i = 0; i < keys.size(); ++i) t.insert_or_assign(keys[i], values[i]);
      },
      [this, keys] {
        for (const auto& k : keys) {
          const std::string name = "control." + k;
          if (std::find(restart_needed_.begin(), restart_needed_.end(), name) ==
              restart_needed_.end()) {
            restart_needed_.push_back(name);
          }
        }
        return json{{"restart_needed", restart_needed_}};
      },
      std::move(done));
}

}  // namespace azt::app
