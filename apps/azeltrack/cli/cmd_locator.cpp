#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "azt/astro/maidenhead.hpp"
#include "cli/commands.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

struct LocatorOptions {
  std::string locator;
  std::string lat, lon;
  int chars = 6;
  bool json = false;
};

int decode(const LocatorOptions& o) {
  auto square = astro::decode_locator(o.locator);
  if (!square) throw UsageError(square.error().message);
  if (o.json) {
    std::cout << nlohmann::json{{"locator", o.locator},
                                {"lat_deg", square->lat_deg},
                                {"lon_deg", square->lon_deg},
                                {"height_deg", square->height_deg},
                                {"width_deg", square->width_deg}}
                     .dump()
              << '\n';
  } else {
    std::cout << std::fixed << std::setprecision(6) << o.locator << ": centre " << square->lat_deg
              << ", " << square->lon_deg << " (" << square->height_deg << "° × "
              << square->width_deg << "°)\n";
  }
  return 0;
}

int encode(const LocatorOptions& o) {
  const double lat = parse_number_option("--lat", o.lat);
  const double lon = parse_number_option("--lon", o.lon);
  auto grid = astro::encode_locator(lat, lon, o.chars);
  if (!grid) throw UsageError(grid.error().message);
  if (o.json) {
    std::cout << nlohmann::json{{"locator", *grid}, {"lat_deg", lat}, {"lon_deg", lon}}.dump()
              << '\n';
  } else {
    std::cout << *grid << '\n';
  }
  return 0;
}

int run_locator(const LocatorOptions& o) {
  const bool have_position = !o.lat.empty() || !o.lon.empty();
  if (!o.locator.empty() && have_position)
    throw UsageError("give a LOCATOR or --lat/--lon, not both");
  if (!o.locator.empty()) return decode(o);
  if (o.lat.empty() || o.lon.empty())
    throw UsageError("locator: give a LOCATOR, or --lat and --lon");
  return encode(o);
}

}  // namespace

Runner add_locator_command(CLI::App& app) {
  auto opts = std::make_shared<LocatorOptions>();
  CLI::App* cmd = app.add_subcommand(
      "locator", "Maidenhead locator to the square's centre, or --lat/--lon to a locator");
  cmd->add_option("locator", opts->locator, "Locator of 4, 6, 8 or 10 characters (FN06HE)");
  cmd->add_option("--lat", opts->lat, "Latitude, degrees north");
  cmd->add_option("--lon", opts->lon, "Longitude, degrees east");
  cmd->add_option("--chars", opts->chars,
                  "Locator length for --lat/--lon: 4, 6, 8 or 10 (default 6)");
  cmd->add_flag("--json", opts->json, "Print one JSON object");
  return [opts] { return run_locator(*opts); };
}

}  // namespace azt::app
