// TLE parsing: strict, column by column, every problem named with its line and column (columns
// 1-based as in the format documents, so a message can be checked against a printed TLE).

#include "azt/orbit/tle.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "azt/util/parse_number.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::orbit {

namespace {

constexpr std::size_t kLineLength = 69;
constexpr std::size_t kChecksumColumn = 69;

/// One TLE line and its number in the file (or 1 and 2 for a lone pair), for messages.
struct Line {
  std::string_view text;
  int number = 0;
};

Error at(const Line& line, std::size_t column, std::string_view field, std::string_view problem) {
  std::string message = "line " + std::to_string(line.number) + ", column " +
                        std::to_string(column) + ": " + std::string(field);
  message += ": ";
  message += problem;
  return fail(std::move(message));
}

/// Columns first..last (1-based, inclusive) of a line already checked to be 69 long.
std::string_view columns(const Line& line, std::size_t first, std::size_t last) {
  return line.text.substr(first - 1, last - first + 1);
}

char column(const Line& line, std::size_t col) { return line.text[col - 1]; }

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string_view trim_right(std::string_view text) {
  while (!text.empty() && (text.back() == ' ' || text.back() == '\r' || text.back() == '\t' ||
                           text.back() == '\n')) {
    text.remove_suffix(1);
  }
  return text;
}

std::string_view trim_left_spaces(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  return text;
}

Result<bool> check_length(const Line& line) {
  if (line.text.size() < kLineLength) {
    return at(
        line, line.text.size() + 1, "line",
        "ends early: a TLE line has 69 characters, this one " + std::to_string(line.text.size()));
  }
  if (line.text.size() > kLineLength) {
    return at(line, kLineLength + 1, "line", "text after the checksum in column 69");
  }
  return true;
}

/// The columns the format leaves blank between fields must be blank: a shifted field is caught
/// here rather than read as a wrong number.
template <std::size_t N>
Result<bool> check_blanks(const Line& line, const std::array<std::size_t, N>& blank_columns) {
  for (std::size_t col : blank_columns) {
    if (column(line, col) != ' ') return at(line, col, "separator", "a blank expected");
  }
  return true;
}

Result<bool> check_checksum(const Line& line, const TleOptions& options) {
  const char written = column(line, kChecksumColumn);
  if (!is_digit(written)) return at(line, kChecksumColumn, "checksum", "not a digit");
  const int computed = tle_checksum(line.text);
  if (options.verify_checksum && written - '0' != computed) {
    return at(line, kChecksumColumn, "checksum",
              std::string("line says ") + written + ", its characters add up to " +
                  std::to_string(computed));
  }
  return true;
}

/// A decimal number with an optional sign and point ("  34.2682", "-.00000084"), blanks before.
Result<double> decimal_field(const Line& line, std::size_t first, std::size_t last,
                             std::string_view field) {
  const std::string_view text = trim_left_spaces(columns(line, first, last));
  bool has_digit = false;
  for (char c : text) {
    if (is_digit(c)) {
      has_digit = true;
    } else if (c != '.' && c != '-' && c != '+') {
      return at(line, first, field, "not a number");
    }
  }
  const std::optional<double> value = parse_finite_double(text);
  if (!has_digit || !value) return at(line, first, field, "not a number");
  return *value;
}

/// An unsigned integer, right-justified (blanks before the digits allowed).
Result<long> integer_field(const Line& line, std::size_t first, std::size_t last,
                           std::string_view field) {
  const std::string_view text = trim_left_spaces(columns(line, first, last));
  if (text.empty()) return at(line, first, field, "blank");
  long value = 0;
  for (char c : text) {
    if (!is_digit(c)) return at(line, first, field, "not a whole number");
    value = value * 10 + (c - '0');
  }
  return value;
}

/// The 8-column "implied decimal point and exponent" form: " 12345-3" = +0.12345e-3,
/// "-11606-4" = −0.11606e-4. Read as Vallado's twoline2rv does: the mantissa as a decimal, then
/// multiplied by pow(10, exponent), so the double is the reference code's to the last bit.
Result<double> exponent_field(const Line& line, std::size_t first, std::string_view field) {
  const char sign = column(line, first);
  const std::string_view digits = columns(line, first + 1, first + 5);
  const char exp_sign = column(line, first + 6);
  const char exp_digit = column(line, first + 7);
  if (sign != ' ' && sign != '+' && sign != '-') return at(line, first, field, "bad sign");
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (!is_digit(digits[i])) return at(line, first + 1 + i, field, "mantissa: not a digit");
  }
  if (exp_sign != '+' && exp_sign != '-' && exp_sign != ' ') {
    return at(line, first + 6, field, "exponent: a sign expected");
  }
  if (!is_digit(exp_digit)) return at(line, first + 7, field, "exponent: not a digit");
  std::string mantissa_text = (sign == '-') ? "-0." : "0.";
  mantissa_text += digits;
  const double mantissa = parse_finite_double(mantissa_text).value_or(0.0);
  const int exponent = (exp_sign == '-' ? -1 : 1) * (exp_digit - '0');
  return mantissa * std::pow(10.0, exponent);
}

/// An angle in degrees within [0, max_deg].
Result<double> angle_field(const Line& line, std::size_t first, std::size_t last,
                           std::string_view field, double max_deg) {
  Result<double> value = decimal_field(line, first, last, field);
  if (!value) return value;
  if (*value < 0.0 || *value > max_deg) {
    return at(line, first, field, "out of range 0–" + std::to_string(static_cast<int>(max_deg)));
  }
  return value;
}

/// The catalogue number field (columns 3–7 of both lines), checked; the text as written.
Result<std::string> catalog_field(const Line& line) {
  const std::string_view text = trim_left_spaces(columns(line, 3, 7));
  Result<long> number = catalog_number(text);
  if (!number) return at(line, 3, "catalogue number", number.error().message);
  return std::string(text);
}

/// The first line's catalogue number (columns 3–7) as a label, if it reads as one.
std::string label_from_line1(std::string_view line1) {
  if (line1.size() < 7) return {};
  const std::string_view text = trim_left_spaces(line1.substr(2, 5));
  return catalog_number(text) ? std::string(text) : std::string();
}

Result<bool> parse_epoch(const Line& line, Elements& e) {
  const std::string_view year_text = columns(line, 19, 20);
  if (!is_digit(year_text[0]) || !is_digit(year_text[1])) {
    return at(line, 19, "epoch", "not a number");
  }
  Result<double> day = decimal_field(line, 21, 32, "epoch");
  if (!day) return day.error();
  // Day 1.0 is 0 h on 1 January; 366.x occurs in leap years (and, as "December 32", in TLEs
  // that some generators write for the first hours of a new year).
  if (*day < 1.0 || *day >= 367.0) return at(line, 21, "epoch", "day of year out of range 1–366");
  const int two_digit_year = (year_text[0] - '0') * 10 + (year_text[1] - '0');
  const JulianDate jd = tle_epoch_to_jd(two_digit_year, *day);
  e.epoch_jd = jd.whole;
  e.epoch_jd_frac = jd.fraction;
  return true;
}

Result<bool> parse_line1(const Line& line, Elements& e) {
  constexpr std::array<std::size_t, 8> kBlanks = {2, 9, 18, 33, 44, 53, 62, 64};
  if (Result<bool> ok = check_blanks(line, kBlanks); !ok) return ok;
  Result<std::string> catalog = catalog_field(line);
  if (!catalog) return catalog.error();
  e.catalog = *catalog;
  const char classification = column(line, 8);
  if (classification != 'U' && classification != 'C' && classification != 'S' &&
      classification != ' ') {
    return at(line, 8, "classification", "U, C or S expected");
  }
  e.classification = classification == ' ' ? 'U' : classification;
  e.intl_designator = std::string(trim_right(columns(line, 10, 17)));
  if (Result<bool> ok = parse_epoch(line, e); !ok) return ok;
  Result<double> ndot = decimal_field(line, 34, 43, "first derivative of mean motion");
  Result<double> nddot = exponent_field(line, 45, "second derivative of mean motion");
  Result<double> bstar = exponent_field(line, 54, "B*");
  for (const Result<double>* r : {&ndot, &nddot, &bstar}) {
    if (!*r) return r->error();
  }
  const char ephemeris_type = column(line, 63);
  if (!is_digit(ephemeris_type) && ephemeris_type != ' ') {
    return at(line, 63, "ephemeris type", "a digit expected");
  }
  Result<long> set_no = integer_field(line, 65, 68, "element set number");
  if (!set_no) return set_no.error();
  e.mean_motion_dot = *ndot;
  e.mean_motion_ddot = *nddot;
  e.bstar = *bstar;
  e.element_set_no = *set_no;
  return true;
}

Result<bool> parse_eccentricity(const Line& line, Elements& e) {
  const std::string_view digits = columns(line, 27, 33);
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (!is_digit(digits[i])) return at(line, 27 + i, "eccentricity", "not a digit");
  }
  // Implied leading decimal point; read as "0.dddddddd" like the reference code.
  e.eccentricity = parse_finite_double("0." + std::string(digits)).value_or(0.0);
  return true;
}

Result<bool> parse_line2(const Line& line, Elements& e) {
  constexpr std::array<std::size_t, 7> kBlanks = {2, 8, 17, 26, 34, 43, 52};
  if (Result<bool> ok = check_blanks(line, kBlanks); !ok) return ok;
  Result<std::string> catalog = catalog_field(line);
  if (!catalog) return catalog.error();
  if (catalog_number(*catalog).value() != catalog_number(e.catalog).value()) {
    return at(line, 3, "catalogue number",
              "'" + *catalog + "' differs from line 1's '" + e.catalog + "'");
  }
  Result<double> incl = angle_field(line, 9, 16, "inclination", 180.0);
  Result<double> raan = angle_field(line, 18, 25, "right ascension of the node", 360.0);
  if (Result<bool> ok = parse_eccentricity(line, e); !ok) return ok;
  Result<double> argp = angle_field(line, 35, 42, "argument of perigee", 360.0);
  Result<double> anomaly = angle_field(line, 44, 51, "mean anomaly", 360.0);
  Result<double> motion = decimal_field(line, 53, 63, "mean motion");
  for (const Result<double>* r : {&incl, &raan, &argp, &anomaly, &motion}) {
    if (!*r) return r->error();
  }
  if (*motion <= 0.0) return at(line, 53, "mean motion", "must be above 0 rev/day");
  Result<long> revs = integer_field(line, 64, 68, "revolution number");
  if (!revs) return revs.error();
  e.inclination_deg = *incl;
  e.raan_deg = *raan;
  e.arg_perigee_deg = *argp;
  e.mean_anomaly_deg = *anomaly;
  e.mean_motion_rev_day = *motion;
  e.rev_at_epoch = *revs;
  return true;
}

/// Line 0 of a three-line set without its Space-Track "0 " prefix and trailing blanks.
std::string clean_name(std::string_view name) {
  name = trim_right(name);
  if (name.size() >= 2 && name[0] == '0' && name[1] == ' ') name.remove_prefix(2);
  return std::string(trim_left_spaces(name));
}

/// The entry's label for messages: its name, else its catalogue number, else "entry".
std::string entry_label(const std::string& name, std::string_view line1) {
  if (!name.empty()) return name;
  std::string number = label_from_line1(line1);
  return number.empty() ? std::string("entry") : number;
}

Result<Elements> parse_entry(const std::string& name, const Line& line1, const Line& line2,
                             const TleOptions& options) {
  Elements e;
  e.name = name;
  const std::array<std::pair<const Line*, char>, 2> lines = {{{&line1, '1'}, {&line2, '2'}}};
  for (const auto& [line, digit] : lines) {
    if (Result<bool> ok = check_length(*line); !ok) return ok.error();
    if (column(*line, 1) != digit) {
      return at(*line, 1, "line number", std::string("'") + digit + "' expected");
    }
    if (Result<bool> ok = check_checksum(*line, options); !ok) return ok.error();
  }
  if (Result<bool> ok = parse_line1(line1, e); !ok) return ok.error();
  if (Result<bool> ok = parse_line2(line2, e); !ok) return ok.error();
  return e;
}

Error labelled(const std::string& label, const Error& error) {
  return fail(label + ": " + error.message);
}

enum class LineKind { Name, First, Second };

LineKind classify(std::string_view line) {
  if (line.size() >= 2 && line[1] == ' ') {
    if (line[0] == '1') return LineKind::First;
    if (line[0] == '2') return LineKind::Second;
  }
  return LineKind::Name;
}

/// Walks a catalogue line by line, pairing names, first and second lines.
class CatalogueReader {
 public:
  explicit CatalogueReader(const TleOptions& options) : options_(options) {}

  void feed(std::string_view text, int number) {
    const std::string_view line = trim_right(text);
    if (line.empty()) return;
    switch (classify(line)) {
      case LineKind::Name:
        drop_pending_line1();
        drop_pending_name();
        name_ = clean_name(line);
        name_line_ = number;
        break;
      case LineKind::First:
        drop_pending_line1();
        line1_ = Line{line, number};
        break;
      case LineKind::Second:
        take_second(Line{line, number});
        break;
    }
  }

  TleParse finish() {
    drop_pending_line1();
    drop_pending_name();
    return std::move(result_);
  }

 private:
  void take_second(const Line& line2) {
    if (!line1_) {
      const std::string label = name_line_ ? name_ : entry_label({}, line2.text);
      result_.errors.push_back(label + ": line " + std::to_string(line2.number) +
                               ": a second line without a first line before it");
      name_.clear();
      name_line_ = 0;
      return;
    }
    Result<Elements> entry = parse_entry(name_, *line1_, line2, options_);
    if (entry) {
      result_.sets.push_back(std::move(entry).value());
    } else {
      result_.errors.push_back(labelled(entry_label(name_, line1_->text), entry.error()).message);
    }
    line1_.reset();
    name_.clear();
    name_line_ = 0;
  }

  void drop_pending_line1() {
    if (!line1_) return;
    result_.errors.push_back(entry_label(name_, line1_->text) + ": line " +
                             std::to_string(line1_->number) +
                             ": a first line without its second line");
    line1_.reset();
    name_.clear();
    name_line_ = 0;
  }

  void drop_pending_name() {
    if (name_line_ == 0) return;
    result_.errors.push_back((name_.empty() ? std::string("entry") : name_) + ": line " +
                             std::to_string(name_line_) + ": a name without element lines");
    name_.clear();
    name_line_ = 0;
  }

  const TleOptions& options_;
  TleParse result_;
  std::string name_;
  int name_line_ = 0;  ///< 0 = no pending name
  std::optional<Line> line1_;
};

}  // namespace

int tle_checksum(std::string_view line) {
  int sum = 0;
  for (std::size_t i = 0; i < line.size() && i < kChecksumColumn - 1; ++i) {
    if (is_digit(line[i])) {
      sum += line[i] - '0';
    } else if (line[i] == '-') {
      sum += 1;
    }
  }
  return sum % 10;
}

Result<long> catalog_number(std::string_view field) {
  const auto bad = [&] {
    return fail("'" + std::string(field) + "' is neither a number nor alpha-5");
  };
  if (field.empty()) return fail("blank");
  long value = 0;
  const char lead = field.front();
  if (is_digit(lead)) {
    value = lead - '0';
  } else if (lead >= 'A' && lead <= 'Z' && lead != 'I' && lead != 'O') {
    // Alpha-5: A=10 … H=17, J=18 … N=22, P=23 … Z=33 (I and O skipped, they read as 1 and 0),
    // always followed by four digits: "A0001" = 100001.
    if (field.size() != 5) return bad();
    value = 10 + (lead - 'A') - (lead > 'I' ? 1 : 0) - (lead > 'O' ? 1 : 0);
  } else {
    return bad();
  }
  for (char c : field.substr(1)) {
    if (!is_digit(c)) return bad();
    value = value * 10 + (c - '0');
  }
  return value;
}

JulianDate tle_epoch_to_jd(int two_digit_year, double day_of_year) {
  const int year = two_digit_year < 57 ? 2000 + two_digit_year : 1900 + two_digit_year;
  // Vallado's days2mdhms: month and day from the day of year (the simple leap rule holds for
  // 1957–2056), then hours, minutes and seconds from the fraction, in this order and rounding.
  std::array<int, 13> month_days = {0, 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (year % 4 == 0) month_days[2] = 29;
  const int whole_day = static_cast<int>(std::floor(day_of_year));
  int month = 1;
  int days_before = 0;
  while (whole_day > days_before + month_days.at(static_cast<std::size_t>(month)) && month < 12) {
    days_before += month_days.at(static_cast<std::size_t>(month));
    ++month;
  }
  const int day = whole_day - days_before;
  double temp = (day_of_year - whole_day) * 24.0;
  const double hour = std::floor(temp);
  temp = (temp - hour) * 60.0;
  const double minute = std::floor(temp);
  const double second = (temp - minute) * 60.0;
  // Vallado's jday, in its split form (Julian date at 0 h, fraction of the day).
  JulianDate jd;
  jd.whole = 367.0 * year - std::floor((7 * (year + std::floor((month + 9) / 12.0))) * 0.25) +
             std::floor(275 * month / 9.0) + day + 1721013.5;
  jd.fraction = (second + minute * 60.0 + hour * 3600.0) / 86400.0;
  if (std::fabs(jd.fraction) > 1.0) {
    const double days = std::floor(jd.fraction);
    jd.whole += days;
    jd.fraction -= days;
  }
  return jd;
}

Result<Elements> parse_tle(std::string_view line1, std::string_view line2, std::string_view name,
                           const TleOptions& options) {
  const std::string clean = clean_name(name);
  const Line first{trim_right(line1), 1};
  const Line second{trim_right(line2), 2};
  Result<Elements> entry = parse_entry(clean, first, second, options);
  if (!entry) return labelled(entry_label(clean, first.text), entry.error());
  return entry;
}

TleParse parse_tle_catalogue(std::string_view text, const TleOptions& options) {
  constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
  if (text.substr(0, kUtf8Bom.size()) == kUtf8Bom) text.remove_prefix(kUtf8Bom.size());
  CatalogueReader reader(options);
  int number = 0;
  for (const std::string_view line : split_lines(text)) reader.feed(line, ++number);
  return reader.finish();
}

}  // namespace azt::orbit
