// The schema's sky keys: where the station is, the band and sky settings, the atmosphere
// (sky_config.cpp reads them).
#include <array>

#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<KeySpec, 6> kStation{{
    {.key = "grid",
     .type = KeyType::Text,
     .default_note = "from lat_deg/lon_deg",
     .help = "Maidenhead locator, 4 to 10 characters (`FN06HE`). Used when `lat_deg`/`lon_deg` "
             "are absent; must contain them when both are given. Setting it from the console "
             "removes `lat_deg`/`lon_deg` (the locator's centre becomes the position); a GPS "
             "survey that sets the position removes it",
     .applies = Applies::Live},
    {.key = "lat_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = closed(-90.0, 90.0),
     .help = "WGS84 latitude, north positive; give `lat_deg` and `lon_deg` together (or `grid`). "
             "Setting it from the console removes `grid`, which is derived from the position",
     .applies = Applies::Live},
    {.key = "lon_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = closed(-180.0, 180.0),
     .help = "WGS84 longitude, east positive; with `lat_deg`",
     .applies = Applies::Live},
    {.key = "alt_m",
     .type = KeyType::Number,
     .unit = "m",
     .range = closed(-500.0, 10000.0),
     .default_toml = "0.0",
     .help = "height above the WGS84 ellipsoid",
     .applies = Applies::Live},
    {.key = "dish_m",
     .type = KeyType::Number,
     .unit = "m",
     .range = closed(0.3, 100.0),
     .default_note = "not given",
     .help = "the dish's diameter: with `efficiency` and `[receiver] tsys_k`, the calibration "
             "session estimates which sources a scan can hear ([calibration.md](calibration.md))"},
    {.key = "efficiency",
     .type = KeyType::Number,
     .range = above_up_to(0.0, 1.0),
     .default_note = "not given",
     .help = "the dish's aperture efficiency, as a fraction (0.5 to 0.65 for most amateur "
             "dishes); with `dish_m`"},
}};

constexpr std::array<std::string_view, 3> kEphemerides{"auto", "swiss", "erfa"};

constexpr std::array<KeySpec, 5> kSky{{
    {.key = "band",
     .type = KeyType::Text,
     .default_toml = "\"144\"",
     .help = "band for the Moon echo Doppler, Tsky and Dgrd: `50 70 144 222 432 902 1296 2304 "
             "3400 5760 10368 24048 47088 76032` (MHz; computed at 50.190, 70.200, 144.100 … "
             "76032.100 MHz), or the wavelength `6m 4m 2m 1.25m 70cm 33cm 23cm 13cm 9cm 6cm 3cm "
             "1.2cm 6mm 4mm` (spaces and case ignored), or `3.4g 5.7g 10g 24g 47g 76g`",
     .applies = Applies::Live},
    {.key = "ephemeris",
     .type = KeyType::Choice,
     .choices = kEphemerides,
     .default_toml = "\"auto\"",
     .help = "`auto`: Swiss Ephemeris when built in and its files are installed, else ERFA; "
             "`swiss`; `erfa`"},
    {.key = "dut1_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = within(10.0),
     .default_toml = "0.0",
     .help = "UT1−UTC; accepted with a warning beyond ±0.9 (IERS keeps it within)"},
    {.key = "dx_grid",
     .type = KeyType::Text,
     .default_note = "none",
     .help = "a DX station's locator, for the DX echo Doppler, Dpol and MNR",
     .applies = Applies::Live},
    {.key = "sources",
     .type = KeyType::TextList,
     .default_note = "the whole catalogue",
     .help = "names or aliases of the radio sources to show (`azeltrack sky --list`)"},
}};

constexpr std::array<std::string_view, 3> kRefractionModels{"radio", "optical", "none"};

constexpr std::array<KeySpec, 4> kAtmosphere{{
    {.key = "refraction",
     .type = KeyType::Choice,
     .choices = kRefractionModels,
     .default_toml = "\"radio\"",
     .help = "the refraction model ([sky-engine.md](sky-engine.md))"},
    {.key = "pressure_hpa",
     .type = KeyType::Number,
     .unit = "hPa",
     .range = closed(0.0, 1200.0),
     .default_toml = "1013.25",
     .help = "station pressure (not reduced to sea level)"},
    {.key = "temperature_c",
     .type = KeyType::Number,
     .unit = "°C",
     .range = closed(-60.0, 60.0),
     .default_toml = "10.0",
     .help = "air temperature"},
    {.key = "relative_humidity",
     .type = KeyType::Number,
     .range = closed(0.0, 1.0),
     .default_toml = "0.5",
     .help = "relative humidity, as a fraction"},
}};

constexpr std::array<SectionSpec, 3> kSections{{
    {.name = "station",
     .chapter = Chapter::Sky,
     .keys = kStation,
     .title = "Where the station is",
     .help = "Give `grid`, or `lat_deg` and `lon_deg`."},
    {.name = "sky", .chapter = Chapter::Sky, .keys = kSky, .title = "The sky and the band"},
    {.name = "atmosphere",
     .chapter = Chapter::Sky,
     .keys = kAtmosphere,
     .title = "The atmosphere, for refraction"},
}};

}  // namespace

std::span<const SectionSpec> sky_sections() { return kSections; }

}  // namespace azt::app
