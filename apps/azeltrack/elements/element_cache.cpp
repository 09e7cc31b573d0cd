// The element-set cache's JSON (element_cache.hpp).
#include "elements/element_cache.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace azt::app {
namespace {

constexpr std::string_view kFormat = "azeltrack element cache 1";
constexpr std::size_t kFields = 17;

nlohmann::json set_json(const orbit::Elements& e) {
  return nlohmann::json::array({e.name, e.catalog, e.intl_designator,
                                std::string(1, e.classification), e.epoch_jd, e.epoch_jd_frac,
                                e.mean_motion_dot, e.mean_motion_ddot, e.bstar, e.inclination_deg,
                                e.raan_deg, e.eccentricity, e.arg_perigee_deg, e.mean_anomaly_deg,
                                e.mean_motion_rev_day, e.element_set_no, e.rev_at_epoch});
}

/// Throws nlohmann's type_error for a field of the wrong kind: read_element_cache turns any
/// exception into "not a cache file".
orbit::Elements set_from(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != kFields)
    throw std::runtime_error("an element set of 17 fields expected");
  orbit::Elements e;
  e.name = j[0].get<std::string>();
  e.catalog = j[1].get<std::string>();
  e.intl_designator = j[2].get<std::string>();
  const auto c = j[3].get<std::string>();
  e.classification = c.empty() ? 'U' : c.front();
  double* numbers[] = {
      &e.epoch_jd,        &e.epoch_jd_frac,    &e.mean_motion_dot,    &e.mean_motion_ddot,
      &e.bstar,           &e.inclination_deg,  &e.raan_deg,           &e.eccentricity,
      &e.arg_perigee_deg, &e.mean_anomaly_deg, &e.mean_motion_rev_day};
  std::size_t i = 4;
  for (double* n : numbers) *n = j[i++].get<double>();
  e.element_set_no = j[15].get<std::int64_t>();
  e.rev_at_epoch = j[16].get<std::int64_t>();
  return e;
}

}  // namespace

std::string element_cache_text(const std::vector<CachedSource>& sources) {
  nlohmann::json out{{"format", kFormat}, {"sources", nlohmann::json::array()}};
  for (const CachedSource& s : sources) {
    nlohmann::json sets = nlohmann::json::array();
    for (const orbit::Elements& e : s.sets) sets.push_back(set_json(e));
    out["sources"].push_back({{"url", s.url}, {"last_ok", s.last_ok_unix_s}, {"sets", sets}});
  }
  // Names may hold any bytes a source sent: replaced, never a throw.
  return out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

Result<std::vector<CachedSource>> read_element_cache(std::string_view text) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text.begin(), text.end());
    if (!j.is_object() || j.value("format", "") != kFormat) {
      return fail("not an element cache (no \"format\": \"" + std::string(kFormat) + "\")");
    }
    std::vector<CachedSource> out;
    for (const nlohmann::json& s : j.at("sources")) {
      CachedSource source{s.at("url").get<std::string>(), s.at("last_ok").get<double>(), {}};
      for (const nlohmann::json& set : s.at("sets")) source.sets.push_back(set_from(set));
      out.push_back(std::move(source));
    }
    return out;
  } catch (const std::exception& e) {
    return fail(std::string("not an element cache: ") + e.what());
  }
}

Result<std::string> read_text_file(const std::string& path, std::size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path + ": " + std::strerror(errno));
  std::string text;
  text.resize(max_bytes + 1);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  const auto got = static_cast<std::size_t>(in.gcount());
  if (got > max_bytes) return fail(path + ": over " + std::to_string(max_bytes) + " bytes");
  if (in.bad()) return fail(path + ": cannot be read");
  text.resize(got);
  return text;
}

}  // namespace azt::app
