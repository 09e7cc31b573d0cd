// OMM keywords → Elements: the checks every OMM syntax shares (element_sets.hpp). Ranges
// are the TLE parser's (core/src/orbit/tle.cpp) so that a file's format never changes what is
// accepted.

#include "azt/orbit/omm_record.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "azt/util/parse_number.hpp"

namespace azt::orbit {

namespace {

/// NORAD catalogue numbers have nine digits in OMM (CelesTrak, "A New Way to Obtain GP Data").
constexpr std::int64_t kMaxCatalogNumber = 999'999'999;
/// Element set and revolution numbers: any count a 64-bit integer holds comfortably.
constexpr std::int64_t kMaxCounter = 999'999'999;
/// Values shown in messages are cut here: a fuzzed or binary file must not make a huge message.
constexpr std::size_t kMaxShownChars = 40;

const OmmField* find(const OmmRecord& record, std::string_view key) {
  const auto it = record.fields.find(key);
  if (it == record.fields.end() || it->second.value.empty()) return nullptr;
  return &it->second;
}

Error field_error(int line, std::string_view key, std::string_view problem) {
  std::string message = line > 0 ? "line " + std::to_string(line) + ": " : std::string();
  message += key;
  message += ": ";
  message += problem;
  return fail(std::move(message));
}

/// A keyword not given: the line where its object starts, if the format has lines.
Error missing(const OmmRecord& record, std::string_view key) {
  if (record.line == 0) return field_error(0, key, "missing");
  return field_error(0, key,
                     "missing from the object starting at line " + std::to_string(record.line));
}

std::string shown(std::string_view value) {
  if (value.size() <= kMaxShownChars) return std::string(value);
  return std::string(value.substr(0, kMaxShownChars)) + "…";
}

std::string quoted(std::string_view value) { return "'" + shown(value) + "'"; }

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    const auto upper = [](char c) {
      return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 32) : c;
    };
    return upper(x) == upper(y);
  });
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The allowed interval of a number and how to say it in a message.
struct Limits {
  double min = 0.0;
  double max = 0.0;
  bool min_open = false;  ///< min itself is out
  bool max_open = false;  ///< max itself is out
  std::string_view range_text;
};

Result<double> number(const OmmRecord& record, std::string_view key, const Limits& limits) {
  const OmmField* field = find(record, key);
  if (field == nullptr) return missing(record, key);
  const std::optional<double> value = parse_finite_double(field->value);
  if (!value) return field_error(field->line, key, quoted(field->value) + " is not a number");
  const bool below = limits.min_open ? *value <= limits.min : *value < limits.min;
  const bool above = limits.max_open ? *value >= limits.max : *value > limits.max;
  if (below || above) {
    return field_error(field->line, key,
                       quoted(field->value) + " " + std::string(limits.range_text));
  }
  return *value;
}

/// A whole number, digits only (a '+' allowed), at most `max`; `fallback` when absent.
Result<std::int64_t> whole_number(const OmmRecord& record, std::string_view key,
                                  std::optional<std::int64_t> fallback, std::int64_t max) {
  const OmmField* field = find(record, key);
  if (field == nullptr) {
    if (fallback) return *fallback;
    return missing(record, key);
  }
  std::string_view digits = field->value;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  const bool all_digits = !digits.empty() && std::all_of(digits.begin(), digits.end(), is_digit);
  if (!all_digits) {
    return field_error(field->line, key, quoted(field->value) + " is not a whole number");
  }
  std::int64_t value = 0;
  for (const char c : digits) {
    value = value * 10 + (c - '0');
    if (value > max) {
      return field_error(field->line, key,
                         quoted(field->value) + " is above " + std::to_string(max));
    }
  }
  return value;
}

/// MEAN_ELEMENT_THEORY and the frame keywords: SGP4 elements are TEME, Earth-centred, UTC; a file
/// that says otherwise holds something the propagator would silently misread.
Result<bool> check_metadata(const OmmRecord& record) {
  constexpr std::string_view kTheory = "MEAN_ELEMENT_THEORY";
  const OmmField* theory = find(record, kTheory);
  if (theory == nullptr && record.theory_required) return missing(record, kTheory);
  if (theory != nullptr && !equals_ignoring_case(theory->value, "SGP4")) {
    return field_error(theory->line, kTheory,
                       quoted(theory->value) + ": only SGP4 mean elements can be propagated");
  }
  constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kFixed = {
      {{"CENTER_NAME", "EARTH"}, {"REF_FRAME", "TEME"}, {"TIME_SYSTEM", "UTC"}}};
  for (const auto& [key, expected] : kFixed) {
    const OmmField* field = find(record, key);
    if (field != nullptr && !equals_ignoring_case(field->value, expected)) {
      return field_error(field->line, key,
                         quoted(field->value) + ": SGP4 elements need " + std::string(expected));
    }
  }
  Result<std::int64_t> type = whole_number(record, "EPHEMERIS_TYPE", 0, kMaxCounter);
  if (!type) return type.error();
  if (*type != 0) {
    const OmmField* field = find(record, "EPHEMERIS_TYPE");
    return field_error(field->line, "EPHEMERIS_TYPE",
                       std::to_string(*type) + (*type == 4 ? " (SGP4-XP)" : "") +
                           " is not 0 (SGP4): only SGP4 elements can be propagated");
  }
  return true;
}

/// "1998-067A" → "98067A", the TLE's form; anything else is kept as written.
std::string tle_designator(const std::string& object_id) {
  const std::string_view id = object_id;
  const bool shaped =
      id.size() >= 9 && id.size() <= 11 && id[4] == '-' &&
      std::all_of(id.begin(), id.begin() + 4, is_digit) &&
      std::all_of(id.begin() + 5, id.begin() + 8, is_digit) &&
      std::all_of(id.begin() + 8, id.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
  if (!shaped) return object_id;
  return std::string(id.substr(2, 2)) + std::string(id.substr(5));
}

Result<bool> fill_identity(const OmmRecord& record, Elements& e) {
  Result<std::int64_t> number =
      whole_number(record, "NORAD_CAT_ID", std::nullopt, kMaxCatalogNumber);
  if (!number) return number.error();
  // Zero-padded to the TLE's five columns, so that "07276" names the object in either format.
  e.catalog = std::to_string(*number);
  if (e.catalog.size() < 5) e.catalog.insert(0, 5 - e.catalog.size(), '0');
  if (const OmmField* name = find(record, "OBJECT_NAME")) e.name = name->value;
  if (const OmmField* id = find(record, "OBJECT_ID")) e.intl_designator = tle_designator(id->value);
  if (const OmmField* field = find(record, "CLASSIFICATION_TYPE")) {
    const std::string& c = field->value;
    if (c != "U" && c != "C" && c != "S") {
      return field_error(field->line, "CLASSIFICATION_TYPE", quoted(c) + ": U, C or S expected");
    }
    e.classification = c.front();
  }
  return true;
}

Result<bool> fill_epoch(const OmmRecord& record, Elements& e) {
  const OmmField* field = find(record, "EPOCH");
  if (field == nullptr) return missing(record, "EPOCH");
  Result<JulianDate> jd = parse_omm_epoch(field->value);
  if (!jd) return field_error(field->line, "EPOCH", jd.error().message);
  e.epoch_jd = jd->whole;
  e.epoch_jd_frac = jd->fraction;
  return true;
}

Result<bool> fill_mean_elements(const OmmRecord& record, Elements& e) {
  constexpr double kHuge = std::numeric_limits<double>::max();
  const Limits motion{0.0, kHuge, true, false, "must be above 0 rev/day"};
  const Limits eccentricity{0.0, 1.0, false, true, "out of range 0 ≤ e < 1"};
  const Limits half_turn{0.0, 180.0, false, false, "out of range 0–180"};
  const Limits full_turn{0.0, 360.0, false, false, "out of range 0–360"};
  const std::array<std::tuple<std::string_view, const Limits*, double*>, 6> fields = {{
      {"MEAN_MOTION", &motion, &e.mean_motion_rev_day},
      {"ECCENTRICITY", &eccentricity, &e.eccentricity},
      {"INCLINATION", &half_turn, &e.inclination_deg},
      {"RA_OF_ASC_NODE", &full_turn, &e.raan_deg},
      {"ARG_OF_PERICENTER", &full_turn, &e.arg_perigee_deg},
      {"MEAN_ANOMALY", &full_turn, &e.mean_anomaly_deg},
  }};
  for (const auto& [key, limits, out] : fields) {
    Result<double> value = number(record, key, *limits);
    if (!value) return value.error();
    *out = *value;
  }
  return true;
}

/// The TLE's drag terms, units as there: ṅ/2 rev/day², n̈/6 rev/day³, B* 1/earth radii. Any
/// finite value, as the TLE's fields allow any they can print.
Result<bool> fill_drag_terms(const OmmRecord& record, Elements& e) {
  constexpr double kHuge = std::numeric_limits<double>::max();
  const Limits any{-kHuge, kHuge, false, false, ""};
  const std::array<std::pair<std::string_view, double*>, 3> fields = {{
      {"MEAN_MOTION_DOT", &e.mean_motion_dot},
      {"MEAN_MOTION_DDOT", &e.mean_motion_ddot},
      {"BSTAR", &e.bstar},
  }};
  for (const auto& [key, out] : fields) {
    Result<double> value = number(record, key, any);
    if (!value) return value.error();
    *out = *value;
  }
  return true;
}

Result<bool> fill_counters(const OmmRecord& record, Elements& e) {
  Result<std::int64_t> set_no = whole_number(record, "ELEMENT_SET_NO", 0, kMaxCounter);
  if (!set_no) return set_no.error();
  Result<std::int64_t> revs = whole_number(record, "REV_AT_EPOCH", 0, kMaxCounter);
  if (!revs) return revs.error();
  e.element_set_no = *set_no;
  e.rev_at_epoch = *revs;
  return true;
}

}  // namespace

void add_field(OmmRecord& record, std::string_view key, std::string_view value, int line) {
  const auto [it, added] =
      record.fields.try_emplace(std::string(key), OmmField{std::string(trim(value)), line});
  if (!added && record.problem.empty()) {
    record.problem = field_error(line, key, "given twice in one object").message;
  }
}

std::string record_label(const OmmRecord& record) {
  if (const OmmField* name = find(record, "OBJECT_NAME")) return shown(name->value);
  if (const OmmField* number = find(record, "NORAD_CAT_ID")) return shown(number->value);
  return {};
}

Result<Elements> elements_from_record(const OmmRecord& record) {
  if (!record.problem.empty()) return fail(record.problem);
  if (Result<bool> ok = check_metadata(record); !ok) return ok.error();
  Elements e;
  using Step = Result<bool> (*)(const OmmRecord&, Elements&);
  // In the order a reader scans an OMM: whose elements, when, then the values.
  constexpr std::array<Step, 5> kSteps = {fill_identity, fill_epoch, fill_mean_elements,
                                          fill_drag_terms, fill_counters};
  for (const Step step : kSteps) {
    if (Result<bool> ok = step(record, e); !ok) return ok.error();
  }
  return e;
}

LineIndex::LineIndex(std::string_view text) {
  starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') starts_.push_back(i + 1);
  }
}

int LineIndex::line_at(std::size_t offset) const {
  const auto after = std::upper_bound(starts_.begin(), starts_.end(), offset);
  return static_cast<int>(after - starts_.begin());
}

}  // namespace azt::orbit
