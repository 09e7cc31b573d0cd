// OMM as CelesTrak's FORMAT=json: an array of flat objects keyed by the OMM keywords, numbers as
// JSON numbers (Space-Track writes them as strings; both are read). A single object is read as a
// one-element file. nlohmann-json keeps no line numbers, so messages name the object by position.

#include <nlohmann/json.hpp>

#include <array>
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "satellites/omm_library_readers.hpp"

namespace azt::app {

namespace {

/// A JSON number back to text: the shortest form that reads as the same double, so the value is
/// exactly the one the file printed (strtod and from_chars both round correctly).
std::string number_text(double value) {
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return ec == std::errc{} ? std::string(buffer.data(), end) : std::string("?");
}

orbit::OmmRecord read_object(const nlohmann::json& object) {
  orbit::OmmRecord record;
  for (const auto& [key, value] : object.items()) {
    if (value.is_string()) {
      orbit::add_field(record, key, value.get_ref<const std::string&>(), 0);
    } else if (value.is_number_unsigned()) {
      orbit::add_field(record, key, std::to_string(value.get<std::uint64_t>()), 0);
    } else if (value.is_number_integer()) {
      orbit::add_field(record, key, std::to_string(value.get<std::int64_t>()), 0);
    } else if (value.is_number_float()) {
      orbit::add_field(record, key, number_text(value.get<double>()), 0);
    } else if (!value.is_null() && record.problem.empty()) {
      // null is "not given"; an array, object or boolean cannot be an OMM value.
      record.problem = key + ": a JSON " + value.type_name() + " where a value is expected";
    }
  }
  return record;
}

}  // namespace

orbit::OmmRecords read_omm_json(std::string_view text) {
  orbit::OmmRecords out;
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    // what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: …".
    const std::string_view what = e.what();
    const std::size_t tag_end = what.find("] ");
    out.errors.push_back("not valid JSON: " + std::string(tag_end == std::string_view::npos
                                                              ? what
                                                              : what.substr(tag_end + 2)));
    return out;
  }
  if (document.is_object()) {
    out.records.push_back(read_object(document));
  } else if (document.is_array()) {
    for (const nlohmann::json& entry : document) {
      if (entry.is_object()) {
        out.records.push_back(read_object(entry));
      } else {
        orbit::OmmRecord record;
        record.problem =
            std::string("a JSON ") + entry.type_name() + " where an object is expected";
        out.records.push_back(std::move(record));
      }
    }
  } else {
    out.errors.push_back(std::string("a JSON ") + document.type_name() +
                         " where an array of objects is expected");
  }
  return out;
}

}  // namespace azt::app
