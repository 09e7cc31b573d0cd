#include "azt/timekeeping/chrony_report.hpp"

#include <charconv>
#include <utility>

#include "azt/util/parse_number.hpp"
#include "azt/util/quote.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::timekeeping {
namespace {

constexpr std::size_t kTrackingFields = 14;
constexpr std::size_t kSourcesFields = 10;
/// chronyc prints 2^32-1 seconds for a source never heard from.
constexpr double kNeverHeardS = 4294967295.0;

std::vector<std::string_view> split_csv(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (auto comma = line.find(','); comma != std::string_view::npos;
       comma = line.find(',', start)) {
    fields.push_back(line.substr(start, comma - start));
    start = comma + 1;
  }
  fields.push_back(line.substr(start));
  return fields;
}

/// The fields of one line, read one at a time; the first that does not parse is the error.
class CsvFields {
 public:
  CsvFields(std::string_view line, std::string what)
      : f_(split_csv(line)), what_(std::move(what)) {}

  [[nodiscard]] std::size_t size() const { return f_.size(); }
  [[nodiscard]] std::string text(std::size_t i) const { return std::string(f_[i]); }

  double number(std::size_t i, const char* name) {
    const auto v = parse_finite_double(f_[i]);
    if (!v) note(i, name);
    return v.value_or(0.0);
  }

  int integer(std::size_t i, const char* name, int base = 10) {
    int out = 0;
    const std::string_view t = f_[i];
    const auto r = std::from_chars(t.data(), t.data() + t.size(), out, base);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size()) note(i, name);
    return out;
  }

  char symbol(std::size_t i, const char* name) {
    if (f_[i].size() != 1) note(i, name);
    return f_[i].empty() ? '?' : f_[i][0];
  }

  [[nodiscard]] bool ok() const { return error_.empty(); }
  [[nodiscard]] Error error() const { return fail(error_); }

 private:
  void note(std::size_t i, const char* name) {
    if (error_.empty()) error_ = what_ + ": the " + name + " is not readable: " + quote(f_[i]);
  }

  std::vector<std::string_view> f_;
  std::string what_;
  std::string error_;
};

Result<ChronySource> parse_source(std::string_view line, std::size_t number) {
  CsvFields f(line, "chronyc sources line " + std::to_string(number));
  if (f.size() != kSourcesFields) {
    return fail("chronyc sources line " + std::to_string(number) + ": " + std::to_string(f.size()) +
                " fields, expected " + std::to_string(kSourcesFields));
  }
  ChronySource s;
  s.mode = f.symbol(0, "mode");
  s.state = f.symbol(1, "state");
  s.name = f.text(2);
  s.stratum = f.integer(3, "stratum");
  s.poll_log2_s = f.integer(4, "polling interval");
  s.reach = f.integer(5, "reach register", 8);
  if (f.text(6) != "-") {
    const double ago = f.number(6, "time since the last sample");
    if (ago < kNeverHeardS) s.last_rx_s = ago;
  }
  s.offset_s = f.number(7, "offset");
  s.measured_offset_s = f.number(8, "measured offset");
  s.error_s = f.number(9, "error");
  if (!f.ok()) return f.error();
  return s;
}

}  // namespace

bool ChronyTracking::synchronised() const {
  return stratum > 0 && leap != "Not synchronised" && !leap.empty();
}

std::string_view mode_name(char mode) {
  switch (mode) {
    case '^':
      return "server";
    case '=':
      return "peer";
    case '#':
      return "refclock";
    default:
      return "unknown";
  }
}

std::string_view state_name(char state) {
  switch (state) {
    case '*':
      return "selected";
    case '+':
      return "combined";
    case '-':
      return "not_combined";
    case '?':
      return "unusable";
    case 'x':
      return "falseticker";
    case '~':
      return "too_variable";
    default:
      return "unknown";
  }
}

Result<ChronyTracking> parse_chrony_tracking(std::string_view csv) {
  const auto lines = split_lines(csv);
  if (lines.empty()) return fail("chronyc tracking: no report");
  CsvFields f(lines.front(), "chronyc tracking");
  if (f.size() != kTrackingFields) {
    return fail("chronyc tracking: " + std::to_string(f.size()) + " fields, expected " +
                std::to_string(kTrackingFields));
  }
  ChronyTracking t;
  t.ref_id_hex = f.text(0);
  t.ref_name = f.text(1);
  t.stratum = f.integer(2, "stratum");
  t.ref_time_unix_s = f.number(3, "reference time");
  t.system_offset_s = -f.number(4, "system time");  // a correction still to apply: opposite sign
  t.last_offset_s = f.number(5, "last offset");
  t.rms_offset_s = f.number(6, "RMS offset");
  t.frequency_ppm = f.number(7, "frequency");
  t.root_delay_s = f.number(10, "root delay");
  t.root_dispersion_s = f.number(11, "root dispersion");
  t.update_interval_s = f.number(12, "update interval");
  t.leap = f.text(13);
  if (!f.ok()) return f.error();
  return t;
}

Result<std::vector<ChronySource>> parse_chrony_sources(std::string_view csv) {
  std::vector<ChronySource> sources;
  std::size_t number = 0;
  for (const auto line : split_lines(csv)) {
    ++number;
    if (trim(line).empty()) continue;
    auto s = parse_source(line, number);
    if (!s) return s.error();
    sources.push_back(std::move(s).value());
  }
  return sources;
}

}  // namespace azt::timekeeping
