#include "azt/astro/horizons.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/astro/hermite.hpp"
#include "azt/util/parse_number.hpp"
#include "azt/util/text_lines.hpp"
#include "horizons_text.hpp"

// JPL Horizons vector tables (EPHEM_TYPE='VECTORS'): the header checks that refuse what the
// controller cannot use, the CSV and text records, and Hermite interpolation between them.

namespace azt::astro {
namespace {

using horizons_text::Body;
using horizons_text::bracket;
using horizons_text::column_block;
using horizons_text::days_between;
using horizons_text::find_body;
using horizons_text::header_field;
using horizons_text::HeaderField;
using horizons_text::kAuKm;
using horizons_text::line_error;
using horizons_text::Lines;
using horizons_text::offsets_from_first;
using horizons_text::out_of_span;
using horizons_text::parse_field;
using horizons_text::parse_jd;
using horizons_text::split_commas;
using horizons_text::without_source_note;

constexpr double kSecondsPerDay = 86400.0;

constexpr std::string_view kVectors = "Horizons vector table";

struct UnitScale {
  double pos_to_au;
  double vel_to_au_d;
};

/// Refuses a header line unless `ok`, naming it.
std::optional<Error> require(bool ok, const HeaderField& field, std::string_view why) {
  if (ok) return std::nullopt;
  return line_error(kVectors, field.index, field.line, why);
}

std::optional<Error> check_frame(const Lines& lines, std::size_t soe) {
  const auto frame = header_field(lines, soe, "Reference frame");
  if (!frame) return fail(std::string(kVectors) + ": no \"Reference frame :\" header line");
  // API replies say "ICRF" (REF_PLANE='FRAME') or "Ecliptic of J2000.0"; older ones say
  // "ICRF/J2000.0" and give the plane in "Coordinate systm :".
  const bool icrf = frame->value == "ICRF" || frame->value == "ICRF/J2000.0";
  if (auto e = require(icrf, *frame,
                       "only the ICRF equatorial frame is accepted (REF_SYSTEM='ICRF', "
                       "REF_PLANE='FRAME')")) {
    return e;
  }
  const auto plane = header_field(lines, soe, "Coordinate systm");
  if (!plane) return std::nullopt;
  const bool equatorial = plane->value.find("Equator") != std::string_view::npos &&
                          plane->value.find("Ecliptic") == std::string_view::npos;
  return require(equatorial, *plane,
                 "only the Earth mean equator of J2000 is accepted (REF_PLANE='FRAME'), not the "
                 "ecliptic");
}

std::optional<Error> check_center_and_type(const Lines& lines, std::size_t soe) {
  const auto center = header_field(lines, soe, "Center body name");
  if (!center) return fail(std::string(kVectors) + ": no \"Center body name :\" header line");
  if (auto e = require(center->value.substr(0, 11) == "Earth (399)", *center,
                       "the states must be geocentric (CENTER='500@399')")) {
    return e;
  }
  if (const auto site = header_field(lines, soe, "Center-site name")) {
    const bool geocentre = site->value == "BODY CENTER" || site->value == "GEOCENTRIC";
    if (auto e = require(geocentre, *site,
                         "the centre must be the Earth's centre (CENTER='500@399'), not a site")) {
      return e;
    }
  }
  if (const auto type = header_field(lines, soe, "Output type")) {
    // Light time and aberration are applied by the controller; corrected states would apply
    // them twice.
    if (auto e = require(type->value.substr(0, 9) == "GEOMETRIC", *type,
                         "only geometric states are accepted (VEC_CORR='NONE')")) {
      return e;
    }
  }
  return std::nullopt;
}

Result<UnitScale> vector_units(const Lines& lines, std::size_t soe) {
  const auto units = header_field(lines, soe, "Output units");
  if (!units) return fail(std::string(kVectors) + ": no \"Output units :\" header line");
  if (units->value == "AU-D") return UnitScale{1.0, 1.0};
  if (units->value == "KM-S") return UnitScale{1.0 / kAuKm, kSecondsPerDay / kAuKm};
  if (units->value == "KM-D") return UnitScale{1.0 / kAuKm, 1.0 / kAuKm};
  return line_error(kVectors, units->index, units->line,
                    "units must be KM-S, KM-D or AU-D (OUT_UNITS)");
}

/// Position and velocity numbers of one record, in file units, with its time.
struct RawRecord {
  std::size_t index;
  JulianDate tdb;
  std::array<double, 6> values;
};

/// CSV records: columns found by name in the column line ("JDTDB, Calendar Date (TDB), X, …").
Result<std::vector<RawRecord>> csv_vector_records(const Lines& lines, const Body& body,
                                                  std::string_view columns_line) {
  const auto names = split_commas(columns_line);
  const auto column = [&names](std::string_view name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const std::array<std::size_t, 7> at{column("JDTDB"), column("X"),  column("Y"), column("Z"),
                                      column("VX"),    column("VY"), column("VZ")};
  if (std::any_of(at.begin(), at.end(), [&names](std::size_t c) { return c == names.size(); })) {
    return fail(std::string(kVectors) +
                ": the column line needs JDTDB, X, Y, Z, VX, VY, VZ (TIME_TYPE='TDB', VEC_TABLE "
                "2 or 3); found \"" +
                std::string(trim(columns_line)) + "\"");
  }
  std::vector<RawRecord> records;
  for (std::size_t i = body.soe + 1; i < body.eoe; ++i) {
    const auto fields = split_commas(lines[i]);
    if (fields.size() < names.size() - 1) {
      return line_error(kVectors, i, lines[i], "too few columns");
    }
    RawRecord r{i, {}, {}};
    const auto jd = parse_jd(fields[at[0]]);
    if (!jd) return line_error(kVectors, i, lines[i], "bad JDTDB");
    r.tdb = *jd;
    for (std::size_t k = 0; k < 6; ++k) {
      const auto v = parse_field(fields[at[k + 1]]);
      if (!v) {
        return line_error(kVectors, i, lines[i],
                          "bad number \"" + std::string(fields[at[k + 1]]) + "\" in column " +
                              std::string(names[at[k + 1]]));
      }
      r.values[k] = *v;
    }
    records.push_back(r);
  }
  return records;
}

/// The numbers of a labelled or unlabelled text line ("X =-1.2E+05 Y = 3.4E+04 Z =…").
Result<std::vector<double>> text_line_numbers(std::string_view line, std::size_t index) {
  std::string spaced(line);
  std::replace(spaced.begin(), spaced.end(), '=', ' ');
  std::vector<double> numbers;
  std::string_view rest = spaced;
  while (!(rest = trim(rest)).empty()) {
    const auto end = rest.find_first_of(" \t");
    const std::string_view token = rest.substr(0, end);
    rest.remove_prefix(token.size());
    const bool label = token.find_first_not_of("XYZVLTRG") == std::string_view::npos;
    if (label) continue;
    const auto v = parse_finite_double(token);
    if (!v) return line_error(kVectors, index, line, "bad number \"" + std::string(token) + "\"");
    numbers.push_back(*v);
  }
  return numbers;
}

/// Text records: a "JD = A.D. date TDB" line, then lines of X Y Z, VX VY VZ (and LT RG RR).
Result<std::vector<RawRecord>> text_vector_records(const Lines& lines, const Body& body) {
  std::vector<RawRecord> records;
  std::vector<double> numbers;
  const auto finish = [&]() -> std::optional<Error> {
    if (records.empty()) return std::nullopt;
    if (numbers.size() < 6) {
      const std::size_t i = records.back().index;
      return line_error(kVectors, i, lines[i], "record has fewer than six numbers (X … VZ)");
    }
    std::copy_n(numbers.begin(), 6, records.back().values.begin());
    numbers.clear();
    return std::nullopt;
  };
  for (std::size_t i = body.soe + 1; i < body.eoe; ++i) {
    const auto equals = lines[i].find(" = A.D.");
    if (equals != std::string_view::npos) {
      if (auto e = finish()) return *e;
      const auto jd = parse_jd(lines[i].substr(0, equals));
      if (!jd) return line_error(kVectors, i, lines[i], "bad JDTDB");
      records.push_back(RawRecord{i, *jd, {}});
      continue;
    }
    if (records.empty()) return line_error(kVectors, i, lines[i], "expected a \"JD = A.D.\" line");
    auto more = text_line_numbers(lines[i], i);
    if (!more) return more.error();
    numbers.insert(numbers.end(), more->begin(), more->end());
  }
  if (auto e = finish()) return *e;
  return records;
}

}  // namespace

Result<SpacecraftTable> SpacecraftTable::parse_horizons_vectors(std::string_view text) {
  const Lines lines = split_lines(text);
  const auto body = find_body(lines, kVectors);
  if (!body) return body.error();
  if (auto e = check_frame(lines, body->soe)) return *e;
  if (auto e = check_center_and_type(lines, body->soe)) return *e;
  const auto scale = vector_units(lines, body->soe);
  if (!scale) return scale.error();
  const auto columns = column_block(lines, body->soe);
  if (columns.empty()) return fail(std::string(kVectors) + ": no column names before $$SOE");
  const std::string_view first_columns = lines[columns.front()];
  if (trim(first_columns).substr(0, 5) != "JDTDB") {
    return line_error(kVectors, columns.front(), first_columns,
                      "times must be TDB Julian dates (TIME_TYPE='TDB')");
  }
  const bool csv = first_columns.find(',') != std::string_view::npos;
  auto records =
      csv ? csv_vector_records(lines, *body, first_columns) : text_vector_records(lines, *body);
  if (!records) return records.error();

  SpacecraftTable table;
  const auto target = header_field(lines, body->soe, "Target body name");
  table.target_ = target ? without_source_note(target->value) : std::string("(unnamed target)");
  std::vector<JulianDate> times;
  std::vector<std::size_t> line_index;
  for (const RawRecord& r : *records) {
    PosVel state;
    for (std::size_t k = 0; k < 3; ++k) {
      state.pos_au[k] = r.values[k] * scale->pos_to_au;
      state.vel_au_d[k] = r.values[k + 3] * scale->vel_to_au_d;
    }
    table.nodes_.push_back(Node{r.tdb, state});
    times.push_back(r.tdb);
    line_index.push_back(r.index);
  }
  auto offsets = offsets_from_first(times, line_index, lines, kVectors);
  if (!offsets) return offsets.error();
  table.offset_days_ = std::move(offsets).value();
  return table;
}

Result<PosVel> SpacecraftTable::at(const JulianDate& tdb) const {
  const double t = days_between(nodes_.front().tdb, tdb);
  const auto i = bracket(offset_days_, t);
  if (!i) {
    return out_of_span(kVectors, target_, "TDB", nodes_.front().tdb, offset_days_.back(), tdb);
  }
  const double h = offset_days_[*i + 1] - offset_days_[*i];
  return hermite(nodes_[*i].state, nodes_[*i + 1].state, h, (t - offset_days_[*i]) / h);
}

}  // namespace azt::astro
