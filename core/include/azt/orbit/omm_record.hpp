#pragma once
// The format-independent middle of the OMM readers (the program's element_sets.hpp): each syntax
// (XML, JSON, KVN, CSV) only collects "KEYWORD → text" per object; one converter turns that into
// Elements, so every format checks the same things and words its errors alike.

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "azt/orbit/elements.hpp"
#include "azt/orbit/tle.hpp"
#include "azt/util/result.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::orbit {

/// One keyword's value as written (trimmed) and its line in the file (0 where the format has
/// no lines to give, JSON).
struct OmmField {
  std::string value;
  int line = 0;
};

/// One object's keywords. A syntax problem found while collecting (a CSV row of the wrong
/// width, a KVN line without '=', a keyword given twice) is kept in `problem` and makes the
/// object an error, reported before anything else about it.
struct OmmRecord {
  int line = 0;  ///< where the object starts, 0 if unknown
  std::map<std::string, OmmField, std::less<>> fields;
  std::string problem;  ///< empty = none; already carries its "line N: " where known
  /// XML and KVN carry the CCSDS metadata, so MEAN_ELEMENT_THEORY must be there; CelesTrak's
  /// JSON and CSV leave it out (SGP4 is implied by the GP data they serve).
  bool theory_required = false;
};

/// What a reader collected: the objects in file order and problems with the file as a whole
/// (messages without the source name).
struct OmmRecords {
  std::vector<OmmRecord> records;
  std::vector<std::string> errors;
};

/// Adds a keyword; a second value for the same keyword becomes the record's problem.
void add_field(OmmRecord& record, std::string_view key, std::string_view value, int line);

/// The label for messages: OBJECT_NAME, else NORAD_CAT_ID, else empty.
std::string record_label(const OmmRecord& record);

/// The checks and conversions shared by every format. Errors read
/// "line 12: MEAN_MOTION: not a number" (or without the line where there is none).
Result<Elements> elements_from_record(const OmmRecord& record);

/// An OMM EPOCH, `YYYY-MM-DDThh:mm:ss[.f…][Z]` or the day-of-year form `YYYY-DDDThh:mm:ss[.f…]`,
/// as the split UTC Julian date the TLE parser gives (whole = the preceding midnight).
Result<JulianDate> parse_omm_epoch(std::string_view text);

/// The two syntaxes with no library behind them (the XML and JSON readers, which use pugixml and
/// nlohmann-json, are the program's: satellites/omm_library_readers.hpp).
OmmRecords read_omm_kvn(std::string_view text);
OmmRecords read_omm_csv(std::string_view text);

/// Blanks, tabs, CR and LF off both ends.
inline std::string_view trim(std::string_view text) { return azt::trim(text, " \t\r\n"); }

/// The lines of a text without their "\n" or "\r\n"; line i is number i + 1.
using azt::split_lines;

/// Byte offset → 1-based line number, by binary search over the line starts.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);
  [[nodiscard]] int line_at(std::size_t offset) const;

 private:
  std::vector<std::size_t> starts_;
};

}  // namespace azt::orbit
