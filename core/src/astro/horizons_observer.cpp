#include "azt/astro/horizons.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/util/parse_number.hpp"
#include "azt/util/text_lines.hpp"
#include "horizons_text.hpp"

// JPL Horizons observer tables (EPHEM_TYPE='OBSERVER', CSV): the columns found by name, the
// site, the UT times, and Lagrange interpolation over the four rows around an instant.

namespace azt::astro {
namespace {

using horizons_text::bracket;
using horizons_text::column_block;
using horizons_text::days_between;
using horizons_text::find_body;
using horizons_text::header_field;
using horizons_text::kAuKm;
using horizons_text::line_error;
using horizons_text::Lines;
using horizons_text::offsets_from_first;
using horizons_text::out_of_span;
using horizons_text::parse_field;
using horizons_text::parse_jd;
using horizons_text::split_commas;
using horizons_text::without_source_note;

constexpr double kFullTurnDeg = 360.0;
constexpr double kHalfTurnDeg = 180.0;

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
