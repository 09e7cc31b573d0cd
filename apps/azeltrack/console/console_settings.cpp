// The console's configuration actions: each saves the keys it changes through the atomic store
// (the file as re-read) and applies them to the running station once saved. The settings of any
// section go through act_settings, checked against the configuration schema; the older routes
// (band, DX locator, offsets, tilt, park slots, corrections) keep their own bodies.
#include "console/daemon_console.hpp"

#include <algorithm>
#include <cstdint>

#include "azt/timekeeping/ntp_servers.hpp"
#include "common/usage_error.hpp"
#include "console/body_fields.hpp"
#include "console/restart_needed.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

toml::table& table_at(toml::table& root, const char* name) {
  if (!root.contains(name)) root.insert(name, toml::table{});
  toml::table* t = root[name].as_table();
  if (t == nullptr) throw ApiError(400, name, std::string("[") + name + "] is not a table");
  return *t;
}

/// The whole file's check names the key at fault ("[station].lat_deg and lon_deg go together"):
/// the refusal carries that key as its field, so the page marks it.
ApiError with_field_at_fault(const ApiError& error, const SettingsChange& change) {
  const std::string message = error.what();
  for (const KeySpec* k : change.keys) {
    if (message.find("]." + std::string(k->key)) != std::string::npos) {
      return ApiError(error.status(), std::string(k->key), message);
    }
  }
  return error;
}

}  // namespace

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
        restart_needed_ = restart_needed(started_, p_.store.root());
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

void DaemonConsole::act_scan_apply(const json& /*body*/, ActDone done) {
  if (p_.scanner == nullptr || !p_.scanner->found()) {
    throw ApiError(409, "", "no scan result to apply: run a scan to its end first");
  }
  if (scan_apply_pending_) throw ApiError(409, "", "the scan result is being applied already");
  const ScanOffsets found = *p_.scanner->found();
  // The beam was on the source where the readings said source + found: take it off the value in
  // the file now, not this process's copy, which `azeltrack config set` may have changed since.
  // The result stays applicable until the save is done: a save refused while another program
  // holds the file must not lose minutes of scanning.
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
        apply_live(LiveApply::Corrections);
        return json::object();
      },
      [this, done = std::move(done)](ActResult result) {
        scan_apply_pending_ = false;
        done(std::move(result));
      });
}

void DaemonConsole::act_correction(const json& body, ActDone done) {
  const bool reset = body.value("reset", false);
  std::string axis;
  std::int32_t steps = 0;
  if (!reset) {
    axis = body_text(body, "axis");
    if (axis != "az" && axis != "el") throw ApiError(400, "axis", "axis must be \"az\" or \"el\"");
    steps = static_cast<std::int32_t>(
        body_whole_number(body, "steps", -1000, 1000,
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

void DaemonConsole::act_band(const json& body, ActDone done) {
  save(
      "band",
      [band = body_text(body, "band")](toml::table& root) {
        table_at(root, "sky").insert_or_assign("band", band);
      },
      [this] {
        apply_live(LiveApply::Band);
        return json{{"band", p_.config.sky.band_name}};
      },
      std::move(done));
}

void DaemonConsole::act_dx(const json& body, ActDone done) {
  save(
      "dx_grid",
      [dx = body_text(body, "dx_grid")](toml::table& root) {
        toml::table& sky = table_at(root, "sky");
        if (dx.empty()) {
          sky.erase("dx_grid");
        } else {
          sky.insert_or_assign("dx_grid", dx);
        }
      },
      [this] {
        apply_live(LiveApply::DxGrid);
        return json{{"dx_grid", p_.config.sky.settings.dx_grid}};
      },
      std::move(done));
}

void DaemonConsole::act_offsets(const json& body, ActDone done) {
  const auto az = body_optional_number(body, "az_offset_deg");
  const auto el = body_optional_number(body, "el_offset_deg");
  if (!az && !el) throw ApiError(400, "az_offset_deg", "give az_offset_deg and/or el_offset_deg");
  save(
      az ? "az_offset_deg" : "el_offset_deg",
      [az, el](toml::table& root) {
        toml::table& t = table_at(root, "corrections");
        if (az) t.insert_or_assign("az_offset_deg", *az);
        if (el) t.insert_or_assign("el_offset_deg", *el);
      },
      [this] {
        apply_live(LiveApply::Corrections);
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
        body_whole_number(body, "index", 0, kEntries - 1, "index must be 0 to 59"));
    value = body_number(body, "value");
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
        apply_live(LiveApply::Corrections);
        return json::object();
      },
      std::move(done));
}

void DaemonConsole::act_park(const json& body, ActDone done) {
  const auto slot =
      static_cast<std::size_t>(body_whole_number(body, "slot", 1, 4, "slot must be 1 to 4"));
  std::optional<std::string> name;
  if (body.contains("name")) name = body_text(body, "name");
  const auto az = body_optional_number(body, "az_deg");
  const auto el = body_optional_number(body, "el_deg");
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
        apply_live(LiveApply::Park);
        return json::object();
      },
      std::move(done));
}

void DaemonConsole::apply_live(LiveApply what) {
  const DaemonConfig& saved = p_.store.config();
  switch (what) {
    case LiveApply::Station:
      p_.config.sky.settings.observer = saved.sky.settings.observer;
      p_.config.sky.settings.grid = saved.sky.settings.grid;
      p_.sky.refollow();
      if (p_.satellites != nullptr) p_.satellites->set_site(p_.config.sky.settings.observer);
      if (p_.schedule != nullptr) p_.schedule->set_observer(p_.config.sky.settings.observer);
      break;
    case LiveApply::Band:
      p_.config.sky.band_name = saved.sky.band_name;
      p_.config.sky.settings.freq_mhz = saved.sky.settings.freq_mhz;
      break;
    case LiveApply::DxGrid:
      p_.config.sky.settings.dx = saved.sky.settings.dx;
      p_.config.sky.settings.dx_grid = saved.sky.settings.dx_grid;
      break;
    case LiveApply::Corrections:
      apply_corrections(saved.station.corrections);
      break;
    case LiveApply::Park:
      p_.config.park = saved.park;
      p_.modes.set_park_slots(p_.config.park);
      break;
    case LiveApply::Schedule:
      p_.config.schedule = saved.schedule;
      if (p_.schedule != nullptr) p_.schedule->set_entries(p_.config.schedule);
      break;
    case LiveApply::Pol:
      p_.config.pol = saved.pol;
      if (p_.pol != nullptr) p_.pol->set_settings(p_.config.pol);
      break;
  }
  snapshot_.unix_s = -1.0;  // the views are computed again with what changed
}

void DaemonConsole::act_settings(const std::string& route, const json& body, ActDone done) {
  SettingsChange change = settings_change(route, body);  // a refusal here changes nothing
  const std::string first = std::string(change.keys.front()->key);
  // Park slots the file lacks before the one changed are written as the station runs them, so
  // that the file's numbering stays the console's.
  ItemFiller fill;
  if (change.section->name == "park") {
    fill = [running = p_.modes.park_slots()](std::size_t i) {
      if (i >= running.size()) throw UsageError("at most 4 [[park]] slots");
      const control::ParkSlot& s = running[i];
      return toml::table{
          {"name", s.name}, {"az_deg", s.position.az_deg}, {"el_deg", s.position.el_deg}};
    };
  }
  save(
      first, store_change(change, std::move(fill)),
      [this, change] { return apply_settings(change); },
      [change, done = std::move(done)](ActResult result) {
        if (result.error) result.error = with_field_at_fault(*result.error, change);
        done(std::move(result));
      });
}

json DaemonConsole::apply_settings(const SettingsChange& change) {
  json applied = json::array();
  json restart = json::array();
  std::vector<LiveApply> paths;
  for (const KeySpec* k : change.keys) {
    const auto path = live_apply_of(change.section->name, k->key);
    (path ? applied : restart).push_back(change.dotted(*k));
    if (path && std::find(paths.begin(), paths.end(), *path) == paths.end()) paths.push_back(*path);
  }
  for (const LiveApply path : paths) apply_live(path);
  return {{"applied", applied}, {"restart", restart}, {"restart_needed", restart_needed_}};
}

json DaemonConsole::config_schema() {
  json out = schema_json_with_values(p_.store.root());
  out["restart_needed"] = restart_needed_;
  return out;
}

}  // namespace azt::app
