#pragma once

// Helpers for the oracle tests: running an outside program, seeded random cases, small
// statistics and angle differences. Test code only (popen, environment, files are fine here; the
// core never sees any of this).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace azt::oracle {

// ---- Running programs --------------------------------------------------------------------------

/// Runs `command` through /bin/sh and captures its stdout. nullopt when the shell cannot be
/// started or the command exits non-zero; `error` (if given) then says which and why.
std::optional<std::string> run_command(const std::string& command, std::string* error = nullptr);

/// True when `program` is found on PATH (through `command -v`).
bool program_on_path(const std::string& program);

/// Single-quotes `text` for /bin/sh.
std::string shell_quote(std::string_view text);

/// A fresh path under the system temp directory, unique for this process (`stem`.<pid>.<n>.`ext`).
std::string temp_path(std::string_view stem, std::string_view ext);

/// Writes `text` to `path`; false on any I/O error.
bool write_file(const std::string& path, std::string_view text);
/// Reads a whole file; nullopt on any I/O error.
std::optional<std::string> read_file(const std::string& path);

/// Runs one of the Python oracles that read cases from a CSV file and write their answers to
/// another (`python3 SCRIPT [ARGS] IN OUT`): `cases` go to a temp file, the answers' text (header
/// first) comes back, both files are removed. nullopt when the oracle fails or writes nothing;
/// `error` then says why. `log`, if given, receives what the oracle printed.
std::optional<std::string> run_csv_oracle(const std::string& script, const std::string& args,
                                          std::string_view cases, std::string& error,
                                          std::string* log = nullptr);

// ---- Parsing program output --------------------------------------------------------------------

/// Splits on '\n', dropping a trailing '\r' on each line and empty lines.
std::vector<std::string_view> split_lines(std::string_view text);
/// Splits a line on `sep` and trims blanks from each field (empty fields are kept).
std::vector<std::string_view> split_fields(std::string_view line, char sep);
/// Locale-free strict number parse (std::from_chars) of a trimmed field; nullopt on junk or
/// non-finite values.
std::optional<double> parse_double(std::string_view field);

// ---- Seeded random cases -----------------------------------------------------------------------

/// The seed for a test's random cases: `default_seed` unless the environment variable
/// AZT_ORACLE_SEED holds a decimal number (to reproduce or widen a run). Always print it.
std::uint64_t oracle_seed(std::uint64_t default_seed);

/// Uniform draws from a std::mt19937_64 with a known seed. The seed goes into every failure
/// message so a failing case can be replayed.
class CaseRng {
 public:
  explicit CaseRng(std::uint64_t seed) : seed_(seed), engine_(seed) {}
  [[nodiscard]] std::uint64_t seed() const { return seed_; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi);
  /// Uniform integer in [0, n), n > 0.
  std::size_t index(std::size_t n);

 private:
  std::uint64_t seed_;
  std::mt19937_64 engine_;
};

/// A random station the oracle tests use: latitude −70..+70°, longitude −180..+180°, height
/// 0..3000 m (the brief's ranges: inhabited latitudes where az/el stay well conditioned).
struct RandomStation {
  double lat_deg = 0.0;
  double lon_deg = 0.0;
  double height_m = 0.0;
};
RandomStation random_station(CaseRng& rng);

/// A random UTC instant as Unix seconds (POSIX: leap seconds not counted) between the starts of
/// `first_year` and `end_year` (exclusive), rounded to whole milliseconds.
double random_unix_seconds(CaseRng& rng, int first_year, int end_year);

/// One random instant in the second half of the UTC day just before each of `step_mjds` (the
/// first days on which a new TAI−UTC applies, i.e. the days after a leap second), rounded to
/// whole milliseconds. Those days are the trap for Julian-date based UTC handling (ERFA and
/// astropy stretch their JD fraction over 86401 s), so the oracle tests always include them.
std::vector<double> leap_eve_unix_seconds(std::span<const double> step_mjds, CaseRng& rng);

/// Unix seconds at 00:00 UTC on 1 January of `year` (proleptic Gregorian).
double unix_seconds_at_year_start(int year);

/// Julian Date (on the POSIX uniform-86400 s day) of Unix time `unix_s`: JD 2440587.5 is
/// 1970-01-01T00:00Z. Computed in long double so the printed value keeps ~1 µs.
long double unix_to_jd(double unix_s);

/// ISO 8601 UTC `YYYY-MM-DDTHH:MM:SS.sss` (no zone letter) of Unix time `unix_s`, formatted
/// here with std::chrono rather than by the code under test. Unlike a Julian date, it means the
/// same instant to every program even on a day that ends in a leap second (ERFA and astropy
/// stretch such a day's JD fraction over 86401 s).
std::string unix_to_iso8601(double unix_s);

/// `value` formatted with `digits` significant digits, "C" locale.
std::string format_number(long double value, int digits = 17);

// ---- Angles ------------------------------------------------------------------------------------

inline constexpr double kArcsecPerDeg = 3600.0;

/// a − b wrapped into (−180, 180] degrees.
double wrap_diff_deg(double a_deg, double b_deg);
/// Azimuth difference measured on the sky: (az_a − az_b) wrapped × cos(el), in arcseconds, so a
/// near-zenith azimuth swing does not count as a pointing error.
double az_on_sky_diff_arcsec(double az_a_deg, double az_b_deg, double el_deg);

// ---- Statistics --------------------------------------------------------------------------------

/// Max |x| and RMS of a set of signed differences, remembering which case was worst.
class Stats {
 public:
  void add(double value, std::string_view label = {});
  [[nodiscard]] std::size_t count() const { return count_; }
  [[nodiscard]] double max_abs() const { return max_abs_; }
  [[nodiscard]] double rms() const;
  [[nodiscard]] double mean() const;
  [[nodiscard]] const std::string& worst_label() const { return worst_label_; }

 private:
  std::size_t count_ = 0;
  double sum_ = 0.0;
  double sum_sq_ = 0.0;
  double max_abs_ = 0.0;
  std::string worst_label_;
};

/// A row of a summary table: quantity, unit, the statistics, and the bar (nullopt = reported
/// only, not asserted).
struct SummaryRow {
  std::string quantity;
  std::string unit;
  Stats stats;
  std::optional<double> bar;
};

/// A fixed-width table (quantity, n, max |diff|, RMS, mean, bar, pass) for the test log.
std::string format_summary(std::string_view title, std::span<const SummaryRow> rows);

// ---- Fitting -----------------------------------------------------------------------------------

/// Least-squares polynomial of degree `degree` (≤ 5) through (t_i, y_i); returns its first
/// derivative at t = 0, or nullopt if the system is singular. Used to turn a sampled distance
/// series into a range rate (the oracle README's recommendation, instead of swetest's speed
/// column). The abscissae are rescaled internally for conditioning.
std::optional<double> poly_fit_slope_at_zero(std::span<const double> t, std::span<const double> y,
                                             int degree);

}  // namespace azt::oracle
