#include "station_config.hpp"

#include <toml++/toml.h>

#include <set>

#include "azt/astro/bands.hpp"
#include "azt/astro/maidenhead.hpp"
#include "cli_error.hpp"

namespace azt::app {
namespace {

const std::set<std::string, std::less<>> kStationKeys{"grid", "lat_deg", "lon_deg", "height_m"};
const std::set<std::string, std::less<>> kSkyKeys{"band", "ephemeris", "dut1_s", "dx_grid",
                                                  "sources"};
const std::set<std::string, std::less<>> kAtmosphereKeys{"refraction", "pressure_hpa",
                                                         "temperature_c", "relative_humidity"};

class ConfigReader {
 public:
  ConfigReader(std::string path, const toml::table& root) : path_(std::move(path)), root_(root) {}

  [[noreturn]] void error(const std::string& what) const {
    throw UsageError("config " + path_ + ": " + what);
  }

  const toml::table* table(const char* name, const std::set<std::string, std::less<>>& keys) const {
    const toml::node* node = root_.get(name);
    if (node == nullptr) return nullptr;
    const toml::table* t = node->as_table();
    if (t == nullptr) error(std::string("[") + name + "] must be a table");
    for (const auto& [key, value] : *t) {
      if (keys.count(key.str()) == 0)
        error("unknown key [" + std::string(name) + "]." + std::string(key.str()));
    }
    return t;
  }

  std::optional<double> number(const toml::table* t, const char* section, const char* key) const {
    if (t == nullptr || !t->contains(key)) return std::nullopt;
    auto v = (*t)[key].value<double>();  // accepts integers too
    if (!v) error(std::string("[") + section + "]." + key + " must be a number");
    return v;
  }

  std::optional<std::string> text(const toml::table* t, const char* section,
                                  const char* key) const {
    if (t == nullptr || !t->contains(key)) return std::nullopt;
    auto v = (*t)[key].value<std::string>();
    if (!v) error(std::string("[") + section + "]." + key + " must be a string");
    return v;
  }

 private:
  std::string path_;
  const toml::table& root_;
};

void read_station(const ConfigReader& r, const toml::table* t, SkySettings& sky) {
  if (t == nullptr) r.error("missing [station] table (grid, or lat_deg and lon_deg)");
  const double height_m = r.number(t, "station", "height_m").value_or(0.0);
  const auto grid = r.text(t, "station", "grid");
  const auto lat = r.number(t, "station", "lat_deg");
  const auto lon = r.number(t, "station", "lon_deg");
  if (lat.has_value() != lon.has_value()) r.error("[station] needs both lat_deg and lon_deg");
  try {
    if (lat) {
      sky.observer = observer_from_coordinates(*lat, *lon, height_m);
    } else if (grid) {
      sky.observer = observer_from_grid(*grid, height_m);
    } else {
      r.error("[station] needs grid, or lat_deg and lon_deg");
    }
  } catch (const UsageError& e) {
    r.error(std::string("[station]: ") + e.what());
  }
  sky.grid = grid ? *grid : grid_of(sky.observer);
  if (grid && lat) {
    auto square = astro::decode_locator(*grid);
    if (!square || std::abs(*lat - square->lat_deg) > square->height_deg / 2 ||
        std::abs(*lon - square->lon_deg) > square->width_deg / 2) {
      r.error("[station] grid " + *grid + " does not contain lat_deg/lon_deg");
    }
  }
}

void read_sky(const ConfigReader& r, const toml::table* t, StationConfig& config) {
  SkySettings& sky = config.sky;
  sky.ephemeris = r.text(t, "sky", "ephemeris").value_or("auto");
  sky.dut1_s = r.number(t, "sky", "dut1_s").value_or(0.0);
  try {
    check_dut1(sky.dut1_s);
  } catch (const UsageError& e) {
    r.error(std::string("[sky].dut1_s: ") + e.what());
  }
  config.band_name = r.text(t, "sky", "band").value_or("144");
  const astro::AmateurBand* band = astro::find_band(config.band_name);
  if (band == nullptr) r.error("[sky].band '" + config.band_name + "' is not a known band");
  sky.freq_mhz = band->freq_mhz;
  if (auto dx = r.text(t, "sky", "dx_grid")) {
    sky.dx_grid = *dx;
    try {
      sky.dx = observer_from_grid(*dx, 0.0);
    } catch (const UsageError& e) {
      r.error(std::string("[sky].dx_grid: ") + e.what());
    }
  }
  config.targets = {astro::Target::sun(), astro::Target::moon()};
  const toml::array* sources =
      t != nullptr && t->contains("sources") ? (*t)["sources"].as_array() : nullptr;
  if (t != nullptr && t->contains("sources") && sources == nullptr)
    r.error("[sky].sources must be an array");
  if (sources == nullptr) {
    for (const auto& s : astro::radio_sources())
      config.targets.push_back(astro::Target::radio_source(s));
    return;
  }
  for (const auto& node : *sources) {
    auto name = node.value<std::string>();
    if (!name) r.error("[sky].sources must hold strings");
    auto target = astro::parse_target(*name);
    if (!target) r.error("[sky].sources: " + target.error().message);
    config.targets.push_back(*target);
  }
}

void read_atmosphere(const ConfigReader& r, const toml::table* t, SkySettings& sky) {
  const std::string model_name = r.text(t, "atmosphere", "refraction").value_or("radio");
  auto model = astro::parse_refraction_model(model_name);
  if (!model) r.error("[atmosphere].refraction: " + model.error().message);
  auto atm =
      astro::Atmosphere::make(r.number(t, "atmosphere", "pressure_hpa").value_or(1013.25),
                              r.number(t, "atmosphere", "temperature_c").value_or(10.0),
                              r.number(t, "atmosphere", "relative_humidity").value_or(0.5), *model);
  if (!atm) r.error("[atmosphere]: " + atm.error().message);
  sky.atmosphere = *atm;
}

}  // namespace

StationConfig load_station_config(const std::string& path) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw UsageError("config " + path + ":" + std::to_string(where.line) + ":" +
                     std::to_string(where.column) + ": " + std::string(e.description()));
  }
  const ConfigReader reader(path, root);
  for (const auto& [key, value] : root) {
    const std::string_view k = key.str();
    if (k != "station" && k != "sky" && k != "atmosphere") {
      reader.error("unknown table or key '" + std::string(k) + "'");
    }
  }
  StationConfig config;
  read_station(reader, reader.table("station", kStationKeys), config.sky);
  read_sky(reader, reader.table("sky", kSkyKeys), config);
  read_atmosphere(reader, reader.table("atmosphere", kAtmosphereKeys), config.sky);
  return config;
}

}  // namespace azt::app
