// Element-set files: the format from the content, then the reader for it (element_sets.hpp).
// Detection looks at the content, not the file name: CelesTrak's URLs end in ".php" whatever the
// FORMAT, and people save them under any name.

#include "satellites/element_sets.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "azt/orbit/tle.hpp"
#include "azt/util/valid_utf8.hpp"
#include "satellites/omm_library_readers.hpp"
#include "satellites/satnogs_tle_json.hpp"

namespace azt::app {

namespace {

enum class Format { Empty, Xml, Json, Kvn, Csv, Tle };

/// "SOURCE: message", the form of every error in an ElementSetFile.
std::string from_source(const std::string& source, std::string_view message) {
  std::string text = source;
  text += ": ";
  text += message;
  return text;
}

std::string_view format_name(Format format) {
  switch (format) {
    case Format::Empty:
      return "empty";
    case Format::Xml:
      return "xml";
    case Format::Json:
      return "json";
    case Format::Kvn:
      return "kvn";
    case Format::Csv:
      return "csv";
    case Format::Tle:
      return "tle";
  }
  return "tle";
}

bool has_kvn_header_line(std::string_view text) {
  constexpr std::string_view kVersionKey = "CCSDS_OMM_VERS";
  for (const std::string_view raw : split_lines(text)) {
    if (orbit::trim(raw).substr(0, kVersionKey.size()) == kVersionKey) return true;
  }
  return false;
}

Format detect(std::string_view text) {
  const std::string_view body = orbit::trim(text);
  if (body.empty()) return Format::Empty;
  if (body.front() == '<') return Format::Xml;
  if (body.front() == '[' || body.front() == '{') return Format::Json;
  if (has_kvn_header_line(body)) return Format::Kvn;
  const std::string_view first_line = body.substr(0, body.find('\n'));
  if (first_line.find("OBJECT_NAME") != std::string_view::npos &&
      first_line.find("MEAN_MOTION") != std::string_view::npos) {
    return Format::Csv;
  }
  return Format::Tle;
}

orbit::OmmRecords read_records(Format format, std::string_view text) {
  switch (format) {
    case Format::Xml:
      return read_omm_xml(text);
    case Format::Json:
      return read_omm_json(text);
    case Format::Kvn:
      return orbit::read_omm_kvn(text);
    case Format::Csv:
      return orbit::read_omm_csv(text);
    case Format::Empty:
    case Format::Tle:
      break;
  }
  return {};
}

/// Converts each record; a bad one becomes "SOURCE: object N (LABEL): why".
void convert(const orbit::OmmRecords& records, const std::string& source, ElementSetFile& file) {
  for (const std::string& error : records.errors) file.errors.push_back(from_source(source, error));
  for (std::size_t i = 0; i < records.records.size(); ++i) {
    const orbit::OmmRecord& record = records.records[i];
    Result<orbit::Elements> elements = orbit::elements_from_record(record);
    if (elements) {
      file.sets.push_back(std::move(elements).value());
      continue;
    }
    std::string entry = "object " + std::to_string(i + 1);
    if (const std::string label = orbit::record_label(record); !label.empty()) {
      entry += " (" + label + ")";
    }
    entry += ": ";
    entry += elements.error().message;
    file.errors.push_back(from_source(source, entry));
  }
}

}  // namespace

ElementSetFile parse_element_sets(std::string_view text, const std::string& source_name) {
  constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
  if (text.substr(0, kUtf8Bom.size()) == kUtf8Bom) text.remove_prefix(kUtf8Bom.size());
  ElementSetFile file;
  const Format format = detect(text);
  file.format = std::string(format_name(format));
  if (format == Format::Empty) {
    file.errors.push_back(from_source(source_name, "empty: no element sets in it"));
    return file;
  }
  // SatNOGS DB's JSON carries TLE lines, not OMM keywords: read as the TLEs it holds.
  std::optional<std::string> satnogs;
  if (format == Format::Json) satnogs = satnogs_tle_text(text);
  if (satnogs) file.format = "satnogs-json";
  if (format == Format::Tle || satnogs) {
    orbit::TleParse tles = orbit::parse_tle_catalogue(satnogs ? std::string_view(*satnogs) : text);
    file.sets = std::move(tles.sets);
    for (const std::string& error : tles.errors) {
      file.errors.push_back(from_source(source_name, error));
    }
  } else {
    convert(read_records(format, text), source_name, file);
  }
  // Every outcome says something: a file with nothing in it is an error, not an empty success.
  if (file.sets.empty() && file.errors.empty()) {
    file.errors.push_back(from_source(source_name, "no element sets in it"));
  }
  // Names and messages reach JSON and the log: a Latin-1 name ("ISS Z\xE9RYA") must not throw
  // there (docs/reliability.md "Hardening" row 2), so every text leaves here as valid UTF-8.
  for (auto& set : file.sets) set.name = valid_utf8(set.name);
  for (auto& error : file.errors) error = valid_utf8(error);
  return file;
}

}  // namespace azt::app
