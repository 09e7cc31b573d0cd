#include "azt/astro/horizons.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "azt/astro/hermite.hpp"
#include "azt/util/format_number.hpp"
#include "azt/util/parse_number.hpp"
#include "azt/util/text_lines.hpp"

// Layout of Horizons text output: astroquery's test data (jplhorizons/tests/data/ceres_vectors.txt,
// ceres_ephemerides.txt) and API v1.2 replies; https://ssd-api.jpl.nasa.gov/doc/horizons.html.
// The header is "Key : value" lines; the column names sit between the last two star lines before
// $$SOE; the records run from $$SOE to $$EOE.

namespace azt::astro {
namespace {

constexpr double kAuKm = 149597870.7;  // IAU 2012 B2, as the Horizons header states.
constexpr double kSecondsPerDay = 86400.0;
constexpr double kFullTurnDeg = 360.0;
constexpr double kHalfTurnDeg = 180.0;

using Lines = std::vector<std::string_view>;

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> fields;
  while (true) {
    const auto comma = line.find(',');
    fields.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
  return fields;
}

bool is_star_line(std::string_view line) {
  const auto t = trim(line);
  return !t.empty() && t.find_first_not_of('*') == std::string_view::npos;
}

/// "Horizons vector table, line 28 (Reference frame : Ecliptic of J2000.0): why".
Error line_error(std::string_view table, std::size_t index, std::string_view line,
                 std::string_view why) {
  std::string shown(trim(line).substr(0, 100));
  return fail(std::string(table) + ", line " + std::to_string(index + 1) + " (" + shown +
              "): " + std::string(why));
}

struct HeaderField {
  std::size_t index;
  std::string_view line;
  std::string_view value;
};

/// The header line `key<spaces>: value` before `end`, if any.
std::optional<HeaderField> header_field(const Lines& lines, std::size_t end, std::string_view key) {
  for (std::size_t i = 0; i < end; ++i) {
    const std::string_view line = lines[i];
    if (line.substr(0, key.size()) != key) continue;
    const std::string_view rest = trim(line.substr(key.size()));
    if (rest.empty() || rest.front() != ':') continue;
    return HeaderField{i, line, trim(rest.substr(1))};
  }
  return std::nullopt;
}

/// "Moon (301)                      {source: DE441}" -> "Moon (301)".
std::string without_source_note(std::string_view value) {
  return std::string(trim(value.substr(0, value.find('{'))));
}

struct Body {
  std::size_t soe;  ///< Index of the $$SOE line.
  std::size_t eoe;  ///< Index of the $$EOE line.
};

Result<Body> find_body(const Lines& lines, std::string_view table) {
  const auto is = [](std::string_view marker) {
    return [marker](std::string_view l) { return trim(l) == marker; };
  };
  const auto soe = std::find_if(lines.begin(), lines.end(), is("$$SOE"));
  if (soe == lines.end()) {
    return fail(std::string(table) + ": no $$SOE line (is this Horizons text output?)");
  }
  const auto eoe = std::find_if(soe, lines.end(), is("$$EOE"));
  if (eoe == lines.end()) {
    return fail(std::string(table) + ": no $$EOE line after $$SOE (truncated file?)");
  }
  return Body{static_cast<std::size_t>(soe - lines.begin()),
              static_cast<std::size_t>(eoe - lines.begin())};
}

/// Indices of the column-name lines: between the last two star lines before $$SOE.
std::vector<std::size_t> column_block(const Lines& lines, std::size_t soe) {
  std::size_t i = soe;
  while (i > 0 && !is_star_line(lines[i - 1])) --i;  // $$SOE normally follows a star line
  if (i == 0) return {};
  const std::size_t end = i - 1;
  std::vector<std::size_t> block;
  for (std::size_t k = end; k > 0 && !is_star_line(lines[k - 1]); --k) block.push_back(k - 1);
  std::reverse(block.begin(), block.end());
  return block;
}

std::optional<double> parse_field(std::string_view text) { return parse_finite_double(trim(text)); }

/// A Julian date as written by Horizons ("2460735.506944444"), split at the point so the
/// fraction keeps its ~1e-9 day (86 µs) digits exactly.
std::optional<JulianDate> parse_jd(std::string_view text) {
  text = trim(text);
  const auto point = text.find('.');
  const auto day = parse_finite_double(text.substr(0, point));
  if (!day || *day < 0.0) return std::nullopt;
  if (point == std::string_view::npos) return JulianDate{*day, 0.0};
  const std::string_view digits = text.substr(point + 1);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) {
    return std::nullopt;
  }
  const auto fraction = parse_finite_double("0." + std::string(digits));
  if (!fraction) return std::nullopt;
  return JulianDate{*day, *fraction};
}

double days_between(const JulianDate& from, const JulianDate& to) {
  return (to.jd1 - from.jd1) + (to.jd2 - from.jd2);
}

// ---------------------------------------------------------------------------------------------
// Vector tables

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

/// Strictly increasing node times, counted from the first, or an error naming the record.
template <typename Time>
Result<std::vector<double>> offsets_from_first(const std::vector<Time>& times,
                                               const std::vector<std::size_t>& line_index,
                                               const Lines& lines, std::string_view table) {
  if (times.size() < 2) {
    return fail(std::string(table) + ": needs at least two records between $$SOE and $$EOE");
  }
  std::vector<double> offsets;
  offsets.reserve(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    offsets.push_back(days_between(times.front(), times[k]));
    if (k > 0 && !(offsets[k] > offsets[k - 1])) {
      return line_error(table, line_index[k], lines[line_index[k]],
                        "time is not after the previous record's");
    }
  }
  return offsets;
}

/// Index i with offsets[i] <= t <= offsets[i + 1], or nullopt outside [front, back].
std::optional<std::size_t> bracket(const std::vector<double>& offsets, double t) {
  if (!(t >= offsets.front() && t <= offsets.back())) return std::nullopt;
  const auto upper = std::upper_bound(offsets.begin(), offsets.end(), t);
  const auto i = static_cast<std::size_t>(upper - offsets.begin());
  return std::min(i, offsets.size() - 1) - 1;
}

Error out_of_span(std::string_view table, const std::string& target, std::string_view scale,
                  const JulianDate& first, double last_offset_days, const JulianDate& asked) {
  return fail(std::string(table) + " for " + target + " covers " + std::string(scale) + " JD " +
              format_number(first.total()) + " .. " +
              format_number(first.total() + last_offset_days) + "; asked for JD " +
              format_number(asked.total()));
}

// ---------------------------------------------------------------------------------------------
// Observer tables

constexpr std::string_view kObserver = "Horizons observer table";
constexpr std::size_t kMissing = static_cast<std::size_t>(-1);

struct ObserverColumns {
  std::size_t jd = kMissing;
  std::size_t calendar = kMissing;
  std::size_t az = kMissing;
  std::size_t el = kMissing;
  std::size_t delta = kMissing;
  std::size_t deldot = kMissing;
  std::size_t count = 0;
};

void name_observer_columns(const std::vector<std::string_view>& names, ObserverColumns& c) {
  c.count = names.size();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string_view n = names[i];
    if (n == "Date_________JDUT") c.jd = i;
    if (n.substr(0, 12) == "Date__(UT)__") c.calendar = i;
    if (n == "Azi_(a-app)") c.az = i;
    if (n == "Elev_(a-app)") c.el = i;
    if (n == "Azi____(a-app)___Elev") {  // one name over both columns
      c.az = i;
      c.el = i + 1;
    }
    if (n == "delta") c.delta = i;
    if (n == "deldot") c.deldot = i;
  }
}

Result<ObserverColumns> observer_columns(const Lines& lines, std::size_t soe) {
  const auto block = column_block(lines, soe);
  if (block.size() != 1 || lines[block.front()].find(',') == std::string_view::npos) {
    return fail(std::string(kObserver) +
                ": the column names before $$SOE are not one CSV line (CSV_FORMAT='YES')");
  }
  const std::string_view line = lines[block.front()];
  ObserverColumns c;
  name_observer_columns(split_commas(line), c);
  if (c.jd == kMissing && c.calendar == kMissing) {
    return line_error(kObserver, block.front(), line,
                      "needs a UT time column, Date__(UT)__… or Date_________JDUT");
  }
  if (c.az == kMissing || c.el == kMissing) {
    return line_error(kObserver, block.front(), line,
                      "needs Azi_(a-app) and Elev_(a-app) (QUANTITIES 4, ANG_FORMAT='DEG')");
  }
  if (c.delta == kMissing || c.deldot == kMissing) {
    return line_error(kObserver, block.front(), line, "needs delta and deldot (QUANTITIES 20)");
  }
  return c;
}

/// "Center geodetic : 350.1234, 48.7654, 0.312 {E-lon(deg),Lat(deg),Alt(km)}".
Result<HorizonsSite> observer_site(const Lines& lines, std::size_t soe) {
  const auto center = header_field(lines, soe, "Center body name");
  if (center && center->value.substr(0, 11) != "Earth (399)") {
    return line_error(kObserver, center->index, center->line, "the site must be on the Earth");
  }
  const auto geodetic = header_field(lines, soe, "Center geodetic");
  if (!geodetic) return fail(std::string(kObserver) + ": no \"Center geodetic :\" header line");
  const auto parts = split_commas(geodetic->value.substr(0, geodetic->value.find('{')));
  std::array<double, 3> v{};
  for (std::size_t k = 0; k < v.size(); ++k) {
    const auto x = k < parts.size() ? parse_field(parts[k]) : std::nullopt;
    if (!x) {
      return line_error(kObserver, geodetic->index, geodetic->line,
                        "expected E-lon, lat (degrees), alt (km)");
    }
    v[k] = *x;
  }
  const double lon =
      std::fmod(std::fmod(v[0], kFullTurnDeg) + kFullTurnDeg + kHalfTurnDeg, kFullTurnDeg) -
      kHalfTurnDeg;
  return HorizonsSite{lon, v[1], v[2]};
}

/// delta is in au unless the footer's delta paragraph says "Units: KM" (RANGE_UNITS='KM').
double delta_to_km(const Lines& lines, std::size_t eoe) {
  for (std::size_t i = eoe; i < lines.size(); ++i) {
    if (lines[i].find("'delta,") == std::string_view::npos) continue;
    for (std::size_t k = i; k < std::min(lines.size(), i + 12); ++k) {
      const auto units = lines[k].find("Units:");
      if (units == std::string_view::npos) continue;
      return trim(lines[k].substr(units + 6)).substr(0, 2) == "KM" ? 1.0 : kAuKm;
    }
  }
  return kAuKm;
}

/// "2025-Mar-01 00:10:00.000" (seconds and their fraction optional), as Horizons writes UT.
std::optional<JulianDate> parse_calendar_utc(std::string_view text) {
  static constexpr std::array<std::string_view, 12> kMonths{
      "Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  text = trim(text);
  if (text.size() < 17 || text[4] != '-' || text[8] != '-' || text[11] != ' ' || text[14] != ':') {
    return std::nullopt;
  }
  const auto month = std::find(kMonths.begin(), kMonths.end(), text.substr(5, 3));
  const auto year = parse_finite_double(text.substr(0, 4));
  const auto day = parse_finite_double(text.substr(9, 2));
  const auto hour = parse_finite_double(text.substr(12, 2));
  const auto minute = parse_finite_double(text.substr(15, 2));
  std::optional<double> second = 0.0;
  if (text.size() > 17)
    second = text[17] == ':' ? parse_finite_double(text.substr(18)) : std::nullopt;
  if (month == kMonths.end() || !year || !day || !hour || !minute || !second) return std::nullopt;
  const auto utc = UtcInstant::from_calendar(
      static_cast<int>(*year), static_cast<int>(month - kMonths.begin()) + 1,
      static_cast<int>(*day), static_cast<int>(*hour), static_cast<int>(*minute), *second);
  if (!utc) return std::nullopt;
  return utc->jd;
}

struct ObserverRow {
  JulianDate utc;
  ObserverLook look;
};

Result<ObserverRow> observer_row(std::string_view line, std::size_t index, const ObserverColumns& c,
                                 double delta_km) {
  const auto fields = split_commas(line);
  if (fields.size() + 1 < c.count) return line_error(kObserver, index, line, "too few columns");
  const auto time =
      c.jd != kMissing ? parse_jd(fields[c.jd]) : parse_calendar_utc(fields[c.calendar]);
  if (!time) return line_error(kObserver, index, line, "bad UT time");
  std::array<double, 4> v{};
  const std::array<std::size_t, 4> at{c.az, c.el, c.delta, c.deldot};
  for (std::size_t k = 0; k < at.size(); ++k) {
    const std::string_view field = at[k] < fields.size() ? fields[at[k]] : std::string_view{};
    if (field == "n.a.") {
      return line_error(kObserver, index, line,
                        "a value is n.a. (az/el need a topocentric site, not the geocentre)");
    }
    const auto x = parse_field(field);
    if (!x) return line_error(kObserver, index, line, "bad number \"" + std::string(field) + "\"");
    v[k] = *x;
  }
  return ObserverRow{*time, ObserverLook{v[0], v[1], v[2] * delta_km, v[3]}};
}

/// Lagrange polynomial through (t[k], y[k]), k < n, evaluated at x.
double lagrange(const std::array<double, 4>& t, const std::array<double, 4>& y, std::size_t n,
                double x) {
  double sum = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    double basis = 1.0;
    for (std::size_t m = 0; m < n; ++m) {
      if (m != j) basis *= (x - t[m]) / (t[j] - t[m]);
    }
    sum += basis * y[j];
  }
  return sum;
}

/// Azimuths made continuous across north: each within ±180° of the one before.
void unwrap_deg(std::array<double, 4>& az, std::size_t n) {
  for (std::size_t k = 1; k < n; ++k) {
    az[k] -= kFullTurnDeg * std::round((az[k] - az[k - 1]) / kFullTurnDeg);
  }
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

Result<ObserverTable> ObserverTable::parse_horizons_observer(std::string_view text) {
  const Lines lines = split_lines(text);
  const auto body = find_body(lines, kObserver);
  if (!body) return body.error();
  const auto columns = observer_columns(lines, body->soe);
  if (!columns) return columns.error();
  auto site = observer_site(lines, body->soe);
  if (!site) return site.error();
  const double delta_km = delta_to_km(lines, body->eoe);

  ObserverTable table;
  const auto target = header_field(lines, body->soe, "Target body name");
  table.target_ = target ? without_source_note(target->value) : std::string("(unnamed target)");
  table.site_ = *site;
  std::vector<JulianDate> times;
  std::vector<std::size_t> line_index;
  for (std::size_t i = body->soe + 1; i < body->eoe; ++i) {
    auto row = observer_row(lines[i], i, *columns, delta_km);
    if (!row) return row.error();
    times.push_back(row->utc);
    line_index.push_back(i);
    table.rows_.push_back(row->look);
  }
  auto offsets = offsets_from_first(times, line_index, lines, kObserver);
  if (!offsets) return offsets.error();
  table.first_utc_ = times.front();
  table.times_days_ = std::move(offsets).value();
  return table;
}

Result<ObserverLook> ObserverTable::at(const UtcInstant& utc) const {
  const double t = days_between(first_utc_, utc.jd);
  const auto i = bracket(times_days_, t);
  if (!i) return out_of_span(kObserver, target_, "UTC", first_utc_, times_days_.back(), utc.jd);
  // The four rows around the interval (three or two at the ends of a short table).
  const std::size_t n = std::min<std::size_t>(4, rows_.size());
  const std::size_t first = std::min(*i > 0 ? *i - 1 : 0, rows_.size() - n);
  std::array<double, 4> tk{}, az{}, el{}, range{}, rate{};
  for (std::size_t k = 0; k < n; ++k) {
    const ObserverLook& r = rows_[first + k];
    tk[k] = times_days_[first + k];
    az[k] = r.az_deg;
    el[k] = r.el_deg;
    range[k] = r.range_km;
    rate[k] = r.range_rate_km_s;
  }
  unwrap_deg(az, n);
  double az_deg = std::fmod(lagrange(tk, az, n, t), kFullTurnDeg);
  if (az_deg < 0.0) az_deg += kFullTurnDeg;
  return ObserverLook{az_deg, lagrange(tk, el, n, t), lagrange(tk, range, n, t),
                      lagrange(tk, rate, n, t)};
}

}  // namespace azt::astro
