#pragma once
// SatNOGS DB's element sets as its API serves them by default (`/api/tle/?format=json`): a JSON
// array of objects whose "tle0", "tle1" and "tle2" hold a three-line set's lines, "tle0"
// possibly with its "0 " prefix (round3 notes §4.2; the fields as public clients read them).

#include <optional>
#include <string>
#include <string_view>

namespace azt::app {

/// The sets as TLE text (three lines each) when `text` is such an array (its first object has
/// "tle1"); nullopt for any other JSON (OMM), which the OMM reader takes. An object without
/// string lines gives an empty entry, which the TLE parser names as an error.
std::optional<std::string> satnogs_tle_text(std::string_view text);

}  // namespace azt::app
