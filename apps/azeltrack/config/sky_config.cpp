#include "config/sky_config.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "azt/astro/bands.hpp"
#include "azt/astro/maidenhead.hpp"
#include "azt/astro/target.hpp"
#include "azt/linux/atomic_file.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

void check_grid_contains(const ConfigSection& s, const std::string& grid, double lat, double lon) {
  auto square = astro::decode_locator(grid);
  if (!square || std::abs(lat - square->lat_deg) > square->height_deg / 2 ||
      std::abs(lon - square->lon_deg) > square->width_deg / 2) {
    s.fail("grid", grid + " does not contain lat_deg/lon_deg");
  }
}

void read_station(const ConfigSection& s, SkySettings& sky) {
  if (!s.present()) s.fail("grid", "missing: give [station] grid, or lat_deg and lon_deg");
  const double alt_m = s.number("alt_m").value_or(0.0);
  const auto grid = s.text("grid");
  const auto lat = s.number("lat_deg");
  const auto lon = s.number("lon_deg");
  if (lat.has_value() != lon.has_value()) s.fail("lat_deg", "and lon_deg go together");
  if (!lat && !grid) s.fail("grid", "missing: give grid, or lat_deg and lon_deg");
  try {
    sky.observer =
        lat ? observer_from_coordinates(*lat, *lon, alt_m) : observer_from_grid(*grid, alt_m);
  } catch (const UsageError& e) {
    std::string why = e.what();
    if (why.rfind("--grid: ", 0) == 0) why.erase(0, 8);  // the command line's wording
    s.fail(lat ? "lat_deg" : "grid", why);
  }
  sky.grid = grid ? *grid : grid_of(sky.observer);
  if (grid && lat) check_grid_contains(s, *grid, *lat, *lon);
}

void read_targets(const ConfigSection& s, SkyConfig& config) {
  config.targets = {astro::Target::sun(), astro::Target::moon()};
  const toml::array* sources = s.array("sources");
  if (sources == nullptr) {
    for (const auto& src : astro::radio_sources()) {
      config.targets.push_back(astro::Target::radio_source(src));
    }
    return;
  }
  for (const auto& node : *sources) {
    auto name = node.value<std::string>();
    if (!name) s.fail("sources", "must hold strings");
    auto target = astro::parse_target(*name);
    if (!target) s.fail("sources", target.error().message);
    config.targets.push_back(*target);
  }
}

void read_sky(const ConfigSection& s, SkyConfig& config) {
  SkySettings& sky = config.settings;
  sky.ephemeris = s.text("ephemeris").value_or("auto");
  sky.dut1_s = s.number("dut1_s").value_or(0.0);
  try {
    check_dut1(sky.dut1_s);
  } catch (const UsageError& e) {
    s.fail("dut1_s", e.what());
  }
  config.band_name = s.text("band").value_or("144");
  const astro::AmateurBand* band = astro::find_band(config.band_name);
  if (band == nullptr) s.fail("band", "'" + config.band_name + "' is not a known band");
  sky.freq_mhz = band->freq_mhz;
  if (auto dx = s.text("dx_grid")) {
    sky.dx_grid = *dx;
    try {
      sky.dx = observer_from_grid(*dx, 0.0);
    } catch (const UsageError& e) {
      s.fail("dx_grid", e.what());
    }
  }
  read_targets(s, config);
}

void read_atmosphere(const ConfigSection& s, SkySettings& sky) {
  const std::string model_name = s.text("refraction").value_or("radio");
  auto model = astro::parse_refraction_model(model_name);
  if (!model) s.fail("refraction", model.error().message);
  auto atm = astro::Atmosphere::make(s.number("pressure_hpa").value_or(1013.25),
                                     s.number("temperature_c").value_or(10.0),
                                     s.number("relative_humidity").value_or(0.5), *model);
  if (!atm) s.fail("pressure_hpa", atm.error().message);
  sky.atmosphere = *atm;
}

/// [[spacecraft]]: bodies from JPL Horizons vector tables (seed 000's DSN page). A file that does
/// not read or parse is refused here, naming the entry, rather than found missing mid-session.
void read_spacecraft(const ConfigFile& file, SkyConfig& config) {
  for (const ConfigSection& s : file.section_array("spacecraft")) {
    const auto name = s.text("name");
    const auto path = s.text("file");
    if (!name || name->empty()) s.fail("name", "is required");
    if (!path || path->empty()) s.fail("file", "is required: a JPL Horizons vector table");
    const std::filesystem::path where =
        std::filesystem::path(*path).is_absolute()
            ? std::filesystem::path(*path)
            : std::filesystem::path(file.path()).parent_path() / *path;
    auto text = linux_os::read_file(where.string());
    if (!text) s.fail("file", text.error().message);
    auto table = astro::SpacecraftTable::parse_horizons_vectors(text.value());
    if (!table) s.fail("file", where.string() + ": " + table.error().message);
    const double f = s.number("frequency_mhz").value_or(0.0);
    config.targets.push_back(astro::Target::spacecraft(
        *name, std::make_shared<const astro::SpacecraftTable>(std::move(table).value()),
        s.text("description").value_or(""), f));
  }
}

}  // namespace

SkyConfig sky_config_from(const ConfigFile& file) {
  SkyConfig config;
  read_station(file.section("station"), config.settings);
  read_sky(file.section("sky"), config);
  read_atmosphere(file.section("atmosphere"), config.settings);
  read_spacecraft(file, config);
  return config;
}

SkyConfig load_sky_config(const std::string& path) {
  return sky_config_from(ConfigFile::load(path));
}

std::optional<astro::Target> find_sky_target(const SkyConfig& station, const std::string& name) {
  const auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
  };
  const std::string wanted = lower(name);
  for (const auto& t : station.targets) {
    if (lower(t.name) == wanted) return t;
    if (t.kind == astro::Target::Kind::Moon && wanted == "moon") return t;
    if (t.kind == astro::Target::Kind::Sun && wanted == "sun") return t;
  }
  for (const auto& t : station.targets) {
    std::string compact = lower(t.name);
    compact.erase(std::remove(compact.begin(), compact.end(), ' '), compact.end());
    if (compact == wanted) return t;
  }
  // A catalogue alias ("casa", "crab") of a source this station lists.
  if (const auto parsed = astro::parse_target(name); parsed) {
    for (const auto& t : station.targets) {
      if (t.kind == parsed->kind && t.name == parsed->name) return t;
    }
  }
  return std::nullopt;
}

void set_station_position(toml::table& station, double lat_deg, double lon_deg,
                          std::optional<double> alt_m) {
  station.insert_or_assign("lat_deg", lat_deg);
  station.insert_or_assign("lon_deg", lon_deg);
  if (alt_m) station.insert_or_assign("alt_m", *alt_m);
  station.erase("grid");  // derived from the position
}

}  // namespace azt::app
