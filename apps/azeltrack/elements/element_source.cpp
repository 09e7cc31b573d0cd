// One element source's state (element_source.hpp).
#include "elements/element_source.hpp"

#include <utility>

#include "azt/astro/time_scales.hpp"
#include "satellites/element_sets.hpp"

namespace azt::app {
namespace {

nlohmann::json iso_or_null(const std::optional<double>& unix_s) {
  return unix_s ? nlohmann::json(astro::format_iso8601_utc_unix(*unix_s)) : nlohmann::json();
}

}  // namespace

std::string_view kind_name(SourceKind kind) {
  switch (kind) {
    case SourceKind::Download:
      return "download";
    case SourceKind::File:
      return "file";
    case SourceKind::Upload:
      return "upload";
  }
  return "download";
}

nlohmann::json ElementSource::to_json() const {
  return {{"url", url},
          {"kind", kind_name(kind)},
          {"last_ok", iso_or_null(last_ok_unix_s)},
          {"last_error", last_error.empty() ? nlohmann::json() : nlohmann::json(last_error)},
          {"last_error_at", iso_or_null(last_error_unix_s)},
          {"count", sets->size()}};
}

void ElementSource::failed(std::string why, double unix_s) {
  last_error = std::move(why);
  last_error_unix_s = unix_s;
}

void ElementSource::succeeded(ElementSets fresh, double unix_s) {
  sets = std::move(fresh);
  last_ok_unix_s = unix_s;
  last_error.clear();
}

orbit::ElementDownload read_element_text(std::string_view text, const std::string& source_name) {
  ElementSetFile file = parse_element_sets(text, source_name);
  return orbit::ElementDownload{std::move(file.sets), std::move(file.errors)};
}

}  // namespace azt::app
