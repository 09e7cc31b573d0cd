#pragma once
// Satellites for the command line and the daemon (docs/satellites.md): a catalogue of element sets
// (TLE or OMM) with their SGP4 propagators. Where each one is from a station, and its passes, is
// the core's (azt/orbit/satellite.hpp). A satellite whose elements do not initialise is an error
// for that satellite alone.

#include <optional>
#include <string>
#include <vector>

#include "azt/orbit/satellite.hpp"

namespace azt::app {

class SatelliteCatalogue {
 public:
  /// Parses a catalogue file's text (TLE, or OMM in XML / JSON / KVN / CSV). Entries that do not
  /// parse or initialise are kept as named errors; the others are usable.
  static SatelliteCatalogue parse(std::string_view text, const std::string& source);
  /// A catalogue of sets already read (a merge of several sources, docs/satellites.md): each
  /// gets its propagator; one that does not initialise (a decayed orbit) is a named error.
  static SatelliteCatalogue from_sets(std::vector<orbit::Elements> sets, const std::string& source);
  /// Reads and parses `path`; throws UsageError when it cannot be read.
  static SatelliteCatalogue load(const std::string& path);

  /// By NORAD number, or by name (case-insensitive; an exact match before a unique prefix).
  /// Throws UsageError naming what was asked and, for a name, what is close.
  [[nodiscard]] const orbit::Satellite& find(const std::string& name_or_norad) const;
  [[nodiscard]] const std::vector<orbit::Satellite>& satellites() const { return satellites_; }
  [[nodiscard]] const std::vector<std::string>& errors() const { return errors_; }
  [[nodiscard]] const std::string& source() const { return source_; }

 private:
  std::vector<orbit::Satellite> satellites_;
  std::vector<std::string> errors_;
  std::string source_;
};

}  // namespace azt::app
