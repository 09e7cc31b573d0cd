#pragma once
// Element-set files as CelesTrak and Space-Track serve them (docs/satellites.md): CCSDS OMM in XML,
// JSON, KVN and CSV, or classic TLEs, read into the one structure the propagator takes.
//
// OMM: CCSDS 502.0-B-3 "Orbit Data Messages" (the OMM keywords, KVN and NDM/XML), and CelesTrak's
// "A New Way to Obtain GP Data" (https://celestrak.org/NORAD/documentation/gp-data-formats.php)
// for its JSON and CSV forms, which carry the same keywords flat.

#include <string>
#include <string_view>
#include <vector>

#include "azt/orbit/elements.hpp"

namespace azt::app {

/// What one file gave: the good element sets in file order, one message per bad entry, and the
/// format the content was read as: "xml", "json", "kvn", "csv", "tle", "satnogs-json" (SatNOGS
/// DB's TLE lines in JSON), or "empty".
struct ElementSetFile {
  std::vector<orbit::Elements> sets;
  std::vector<std::string> errors;
  std::string format;
};

/// Reads a whole element-set file, detecting its format from the content (a leading '<' is
/// XML, '[' or '{' JSON (SatNOGS DB's array of "tle0/tle1/tle2" objects, else OMM), a line starting
/// CCSDS_OMM_VERS KVN, a first line naming OBJECT_NAME and
/// MEAN_MOTION a CSV header, anything else TLE through the core parser).
///
/// A malformed entry is an error for that entry alone: the message names the source, the entry
/// (its position, OBJECT_NAME or NORAD_CAT_ID), the line where the format has lines, the keyword
/// and the reason ("celestrak.json: object 3 (NOAA 19): MEAN_MOTION: not a number"). Only a file
/// that cannot be read as its format at all (XML or JSON syntax) gives one error for the file.
/// The result always holds at least one set or one error.
///
/// OMM values as the TLE parser gives them: the same units, the same ranges, the epoch as the
/// split UTC Julian date of tle_epoch_to_jd (whole = the preceding midnight, .5); NORAD_CAT_ID
/// as text zero-padded to 5 digits ("07276", as a TLE writes it; an alpha-5 TLE number A0001
/// is 100001 here), OBJECT_ID "1998-067A" as the TLE designator "98067A". Refused: an
/// EPHEMERIS_TYPE other than 0 (SGP4), a MEAN_ELEMENT_THEORY other than SGP4 (required in XML and
/// KVN), a CENTER_NAME, REF_FRAME or TIME_SYSTEM other than EARTH, TEME, UTC when given.
ElementSetFile parse_element_sets(std::string_view text, const std::string& source_name);

}  // namespace azt::app
