#include "azt/proto/rtl_power_csv.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <system_error>

#include "azt/util/parse_number.hpp"
#include "azt/util/quote.hpp"

namespace azt::proto {
namespace {

/// Date, time, Hz low, Hz high, Hz step, samples.
constexpr std::size_t kHeaderFields = 6;
/// A field quoted in an error message is cut to this, so a hostile line never fills a log.
constexpr std::size_t kShownChars = 24;
/// Longest date or time field: "2024-01-02" and "12:34:56" with room for fractional seconds.
constexpr std::size_t kMaxStampChars = 32;

bool is_blank(char c) { return c == ' ' || c == '\t'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// A field for an error message: quoted, cut short, bytes that are not printable ASCII as '?'
/// (a NUL or an escape sequence from a hostile feed must not reach a log or a terminal).
std::string shown(std::string_view field) {
  std::string printable(field.substr(0, kShownChars + 1));
  for (char& c : printable) {
    if (c < ' ' || c > '~') c = '?';
  }
  return quote(printable, kShownChars);
}

/// The comma-separated fields of one line; the spaces after each comma are not part of a field.
class Fields {
 public:
  explicit Fields(std::string_view line) : rest_(line) {}

  [[nodiscard]] bool done() const { return done_; }
  /// Precondition: !done().
  std::string_view next() {
    const std::size_t comma = rest_.find(',');
    const std::string_view field = rest_.substr(0, comma);
    if (comma == std::string_view::npos) {
      done_ = true;
      rest_ = {};
    } else {
      rest_.remove_prefix(comma + 1);
      while (!rest_.empty() && is_blank(rest_.front())) rest_.remove_prefix(1);
    }
    return field;
  }

 private:
  std::string_view rest_;
  bool done_ = false;
};

bool is_stamp(std::string_view field, std::string_view punctuation) {
  if (field.empty() || field.size() > kMaxStampChars) return false;
  return std::all_of(field.begin(), field.end(), [punctuation](char c) {
    return is_digit(c) || punctuation.find(c) != std::string_view::npos;
  });
}

std::optional<std::int64_t> parse_count(std::string_view field) {
  std::int64_t value = 0;
  const char* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if (field.empty() || ec != std::errc{} || ptr != end || value < 0) return std::nullopt;
  return value;
}

/// Reads the six fields before the bins into `sweep`; an error says which field was wrong.
std::optional<std::string> parse_header(Fields& fields, RtlPowerSweep& sweep) {
  std::array<std::string_view, kHeaderFields> header{};
  for (std::size_t i = 0; i < kHeaderFields; ++i) {
    if (fields.done()) {
      return "rtl_power: " + std::to_string(i) +
             " fields, expected date, time, Hz low, Hz high, "
             "Hz step, samples and the bins";
    }
    header[i] = fields.next();
  }
  if (!is_stamp(header[0], "-")) return "rtl_power: bad date " + shown(header[0]);
  if (!is_stamp(header[1], ":.")) return "rtl_power: bad time " + shown(header[1]);
  const auto low = parse_finite_double(header[2]);
  const auto high = parse_finite_double(header[3]);
  const auto step = parse_finite_double(header[4]);
  const auto samples = parse_count(header[5]);
  if (!low || *low < 0.0) return "rtl_power: bad Hz low " + shown(header[2]);
  if (!high || *high < *low)
    return "rtl_power: bad Hz high " + shown(header[3]) + " (below Hz low)";
  if (!step || *step <= 0.0) return "rtl_power: bad Hz step " + shown(header[4]);
  if (!samples) return "rtl_power: bad sample count " + shown(header[5]);
  sweep.hz_low = *low;
  sweep.hz_high = *high;
  sweep.hz_step = *step;
  sweep.samples = *samples;
  return std::nullopt;
}

/// Reads the bins after the header; stops at the bound before storing more.
std::optional<std::string> parse_bins(Fields& fields, std::size_t commas, RtlPowerSweep& sweep) {
  if (fields.done()) return std::string("rtl_power: no bins after the sample count");
  sweep.bins_db.reserve(std::min(commas, kRtlPowerMaxBins));
  while (!fields.done()) {
    if (sweep.bins_db.size() == kRtlPowerMaxBins) {
      return "rtl_power: more than " + std::to_string(kRtlPowerMaxBins) + " bins";
    }
    const std::string_view field = fields.next();
    const std::string which = "rtl_power: bin " + std::to_string(sweep.bins_db.size() + 1);
    if (field.empty()) return which + " is empty";
    const auto db = parse_finite_double(field);
    // "nan", "-nan", "inf", "-inf": an empty bin, so the sweep did not measure the band (see
    // the header: the line is malformed, not the bin skipped).
    if (!db) return which + " is not a finite number: " + shown(field);
    if (std::fabs(*db) > kRtlPowerMaxAbsBinDb) return which + " is out of range: " + shown(field);
    sweep.bins_db.push_back(*db);
  }
  return std::nullopt;
}

}  // namespace

Result<RtlPowerSweep> parse_rtl_power_line(std::string_view line) {
  if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.empty()) return fail("rtl_power: empty line");
  const auto commas = static_cast<std::size_t>(std::count(line.begin(), line.end(), ','));
  Fields fields(line);
  RtlPowerSweep sweep;
  if (auto problem = parse_header(fields, sweep)) return fail(std::move(*problem));
  if (auto problem = parse_bins(fields, commas, sweep)) return fail(std::move(*problem));
  return sweep;
}

double sweep_power_db(const RtlPowerSweep& sweep) {
  const std::vector<double>& bins = sweep.bins_db;
  if (bins.empty()) return std::numeric_limits<double>::quiet_NaN();
  // Relative to the strongest bin, so 10^(dB/10) neither overflows nor underflows to zero for
  // any finite input: peak + 10·log10(mean(10^((bin − peak)/10))) is the same quantity.
  const double peak_db = *std::max_element(bins.begin(), bins.end());
  double sum = 0.0;
  for (const double db : bins) sum += std::pow(10.0, (db - peak_db) / 10.0);
  return peak_db + 10.0 * std::log10(sum / static_cast<double>(bins.size()));
}

}  // namespace azt::proto
