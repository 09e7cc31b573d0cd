#include "satellites/satellite_catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "azt/linux/atomic_file.hpp"
#include "common/usage_error.hpp"
#include "satellites/element_sets.hpp"

namespace azt::app {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

}  // namespace

SatelliteCatalogue SatelliteCatalogue::parse(std::string_view text, const std::string& source) {
  // TLE or OMM (XML, JSON, KVN, CSV): errors already name the source and the entry.
  ElementSetFile parsed = parse_element_sets(text, source);
  SatelliteCatalogue c = from_sets(std::move(parsed.sets), source);
  c.errors_.insert(c.errors_.begin(), parsed.errors.begin(), parsed.errors.end());
  return c;
}

SatelliteCatalogue SatelliteCatalogue::from_sets(std::vector<orbit::Elements> sets,
                                                 const std::string& source) {
  SatelliteCatalogue c;
  c.source_ = source;
  c.satellites_.reserve(sets.size());
  for (auto& e : sets) {
    auto sgp4 = orbit::Sgp4::make(e);
    if (!sgp4) {
      c.errors_.push_back(source + ": " + e.label() + ": " + sgp4.error().message);
      continue;
    }
    c.satellites_.push_back(orbit::Satellite{std::move(e), std::move(sgp4).value()});
  }
  return c;
}

SatelliteCatalogue SatelliteCatalogue::load(const std::string& path) {
  auto text = linux_os::read_file(path);
  if (!text) throw UsageError("satellite elements: " + text.error().message);
  return parse(text.value(), path);
}

const orbit::Satellite& SatelliteCatalogue::find(const std::string& name_or_norad) const {
  if (all_digits(name_or_norad)) {
    const std::string wanted = name_or_norad.substr(
        std::min(name_or_norad.find_first_not_of('0'), name_or_norad.size() - 1));
    for (const auto& s : satellites_) {
      const std::string& cat = s.elements.catalog;
      const std::string trimmed = cat.substr(std::min(cat.find_first_not_of('0'), cat.size() - 1));
      if (trimmed == wanted) return s;
    }
  }
  const std::string key = lower(name_or_norad);
  const orbit::Satellite* prefix = nullptr;
  int prefixes = 0;
  for (const auto& s : satellites_) {
    const std::string name = lower(s.elements.name);
    if (name == key) return s;
    if (!key.empty() && name.rfind(key, 0) == 0) {
      prefix = &s;
      ++prefixes;
    }
  }
  if (prefixes == 1) return *prefix;
  std::string why = "'" + name_or_norad + "' is not in " + source_;
  if (prefixes > 1) why += " unambiguously (" + std::to_string(prefixes) + " names start so)";
  for (const auto& e : errors_) {
    if (lower(e).find(key) != std::string::npos) why += "; its entry was refused: " + e;
  }
  throw UsageError(why);
}

}  // namespace azt::app
