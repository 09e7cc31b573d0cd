#include "azt/astro/target.hpp"

#include <cctype>
#include <cmath>
#include <string>

#include "azt/util/format_number.hpp"
#include "azt/util/parse_number.hpp"

namespace azt::astro {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string format_radec_name(double ra_deg, double dec_deg) {
  return "RA " + format_number(ra_deg) + " Dec " + format_number(dec_deg);
}

Result<Target> parse_radec(std::string_view spec, std::string_view original) {
  const auto comma = spec.find(',');
  if (comma == std::string_view::npos) {
    return fail("'" + std::string(original) + "': expected radec:RA_DEG,DEC_DEG");
  }
  const auto ra = parse_finite_double(spec.substr(0, comma));
  const auto dec = parse_finite_double(spec.substr(comma + 1));
  if (!ra || !dec) {
    return fail("'" + std::string(original) + "': RA and Dec must be decimal degrees");
  }
  return Target::radec(*ra, *dec);
}

}  // namespace

Target Target::sun() { return Target{Kind::Sun, "Sun", nullptr, 0.0, 0.0, nullptr, "", 0.0}; }
Target Target::moon() { return Target{Kind::Moon, "Moon", nullptr, 0.0, 0.0, nullptr, "", 0.0}; }

Target Target::radio_source(const RadioSource& source) {
  return Target{
      Kind::Source, std::string(source.name), &source, source.ra_deg, source.dec_deg, nullptr, "",
      0.0};
}

Result<Target> Target::radec(double ra_deg, double dec_deg) {
  if (!std::isfinite(ra_deg) || ra_deg < 0.0 || ra_deg >= 360.0) {
    return fail("RA must be in [0, 360) degrees");
  }
  if (!std::isfinite(dec_deg) || dec_deg < -90.0 || dec_deg > 90.0) {
    return fail("Dec must be in [-90, 90] degrees");
  }
  return Target{
      Kind::RaDec, format_radec_name(ra_deg, dec_deg), nullptr, ra_deg, dec_deg, nullptr, "", 0.0};
}

Result<Target> parse_target(std::string_view text) {
  const std::string name = lower(text);
  if (name == "sun") return Target::sun();
  if (name == "moon") return Target::moon();
  constexpr std::string_view kRadec = "radec:";
  if (name.rfind(kRadec, 0) == 0) return parse_radec(text.substr(kRadec.size()), text);
  if (const RadioSource* s = find_radio_source(text)) return Target::radio_source(*s);
  return fail("unknown target '" + std::string(text) +
              "' (sun, moon, a catalogue name from 'azeltrack sky --list', or radec:RA,DEC)");
}

Target Target::spacecraft(std::string name, std::shared_ptr<const SpacecraftTable> table,
                          std::string description, double frequency_mhz) {
  Target t;
  t.kind = Kind::Spacecraft;
  t.name = std::move(name);
  t.table = std::move(table);
  t.description = std::move(description);
  t.frequency_mhz = frequency_mhz;
  return t;
}

Result<Observation> observe(const Target& target, const Ephemeris& ephemeris, const Epoch& epoch,
                            const Station& station, const Atmosphere& atmosphere) {
  Place place;
  switch (target.kind) {
    case Target::Kind::Sun:
      place = observe_sun(epoch, station);
      break;
    case Target::Kind::Moon: {
      auto moon = observe_moon(ephemeris, epoch, station);
      if (!moon) return moon.error();
      place = *moon;
      break;
    }
    case Target::Kind::Source:
    case Target::Kind::RaDec:
      place = observe_icrs(epoch, station, target.ra_deg, target.dec_deg);
      break;
    case Target::Kind::Spacecraft: {
      if (!target.table) return fail(target.name + ": no ephemeris table");
      auto craft = observe_tabulated(*target.table, epoch, station);
      if (!craft) return fail(target.name + ": " + craft.error().message);
      place = *craft;
      break;
    }
  }
  const double el_deg =
      place.el_geometric_deg +
      refraction_deg(place.el_geometric_deg, station.observer.height_m, atmosphere);
  return Observation{place, el_deg};
}

}  // namespace azt::astro
