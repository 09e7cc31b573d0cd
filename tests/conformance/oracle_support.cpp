#include "oracle_support.hpp"

#include <unistd.h>

#include <sys/wait.h>
#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <locale>
#include <sstream>

namespace azt::oracle {

std::optional<std::string> run_command(const std::string& command, std::string* error) {
  // popen is acceptable here: this is test code, and the commands are built by the tests
  // themselves from numbers and quoted paths.
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    if (error != nullptr) *error = "popen failed for: " + command;
    return std::nullopt;
  }
  std::string out;
  std::array<char, 8192> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    out.append(buffer.data(), n);
  }
  const int status = ::pclose(pipe);
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    if (error != nullptr) {
      *error = "command failed (status " + std::to_string(status) + "): " + command +
               (out.empty() ? std::string{} : "\nstdout: " + out.substr(0, 500));
    }
    return std::nullopt;
  }
  return out;
}

bool program_on_path(const std::string& program) {
  return run_command("command -v " + shell_quote(program) + " >/dev/null 2>&1").has_value();
}

std::string shell_quote(std::string_view text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  quoted += '\'';
  return quoted;
}

std::string temp_path(std::string_view stem, std::string_view ext) {
  static int counter = 0;
  ++counter;
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::string name = std::string(stem) + "." + std::to_string(::getpid()) + "." +
                           std::to_string(counter) + "." + std::string(ext);
  return (dir / name).string();
}

bool write_file(const std::string& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  return static_cast<bool>(out);
}

std::optional<std::string> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return buffer.str();
}

std::optional<std::string> run_csv_oracle(const std::string& script, const std::string& args,
                                          std::string_view cases, std::string& error,
                                          std::string* log) {
  const std::string in = temp_path("azt_oracle_cases", "csv");
  const std::string out = temp_path("azt_oracle_out", "csv");
  if (!write_file(in, cases)) {
    error = "cannot write " + in;
    return std::nullopt;
  }
  const auto printed =
      run_command("/usr/bin/python3 " + shell_quote(script) + (args.empty() ? "" : " " + args) +
                      " " + shell_quote(in) + " " + shell_quote(out) + " 2>&1",
                  &error);
  auto text = read_file(out);
  std::remove(in.c_str());
  std::remove(out.c_str());
  if (printed && log != nullptr) *log = *printed;
  if (!printed) return std::nullopt;
  if (!text) error = script + " wrote no " + out + ": " + *printed;
  return text;
}

namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!line.empty()) lines.push_back(line);
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
  return lines;
}

std::vector<std::string_view> split_fields(std::string_view line, char sep) {
  std::vector<std::string_view> fields;
  while (true) {
    const std::size_t at = line.find(sep);
    fields.push_back(trim(line.substr(0, at)));
    if (at == std::string_view::npos) break;
    line.remove_prefix(at + 1);
  }
  return fields;
}

std::optional<double> parse_double(std::string_view field) {
  field = trim(field);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  double value = 0.0;
  const char* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if (field.empty() || ec != std::errc{} || ptr != end || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::uint64_t oracle_seed(std::uint64_t default_seed) {
  const char* env = std::getenv("AZT_ORACLE_SEED");
  if (env == nullptr) return default_seed;
  std::uint64_t seed = 0;
  const std::string_view text(env);
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (ec != std::errc{} || ptr != text.data() + text.size()) return default_seed;
  return seed;
}

double CaseRng::uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(engine_);
}

std::size_t CaseRng::index(std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(engine_);
}

RandomStation random_station(CaseRng& rng) {
  RandomStation station;
  station.lat_deg = rng.uniform(-70.0, 70.0);
  station.lon_deg = rng.uniform(-180.0, 180.0);
  station.height_m = rng.uniform(0.0, 3000.0);
  return station;
}

double unix_seconds_at_year_start(int year) {
  using namespace std::chrono;
  const sys_days day{std::chrono::year{year} / January / 1};
  return static_cast<double>(duration_cast<seconds>(day.time_since_epoch()).count());
}

double random_unix_seconds(CaseRng& rng, int first_year, int end_year) {
  const double lo = unix_seconds_at_year_start(first_year);
  const double hi = unix_seconds_at_year_start(end_year);
  return std::round(rng.uniform(lo, hi) * 1000.0) / 1000.0;
}

std::vector<double> leap_eve_unix_seconds(std::span<const double> step_mjds, CaseRng& rng) {
  constexpr double kUnixEpochMjd = 40587.0;  // 1970-01-01
  std::vector<double> instants;
  for (const double mjd : step_mjds) {
    const double day_start_s = (mjd - 1.0 - kUnixEpochMjd) * 86400.0;
    instants.push_back(std::round((day_start_s + rng.uniform(43200.0, 86399.0)) * 1000.0) / 1000.0);
  }
  return instants;
}

long double unix_to_jd(double unix_s) {
  return 2440587.5L + static_cast<long double>(unix_s) / 86400.0L;
}

std::string unix_to_iso8601(double unix_s) {
  using namespace std::chrono;
  const auto ms = milliseconds{static_cast<std::int64_t>(std::llround(unix_s * 1000.0))};
  const sys_days day = floor<days>(sys_time<milliseconds>{ms});
  const year_month_day ymd{day};
  const hh_mm_ss<milliseconds> hms{ms - day.time_since_epoch()};
  char buf[40];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02d:%02d:%02d.%03d", static_cast<int>(ymd.year()),
                static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()),
                static_cast<int>(hms.hours().count()), static_cast<int>(hms.minutes().count()),
                static_cast<int>(hms.seconds().count()),
                static_cast<int>(hms.subseconds().count()));
  return buf;
}

std::string format_number(long double value, int digits) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << std::setprecision(digits) << value;
  return out.str();
}

double wrap_diff_deg(double a_deg, double b_deg) {
  double d = std::fmod(a_deg - b_deg, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

double az_on_sky_diff_arcsec(double az_a_deg, double az_b_deg, double el_deg) {
  constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;
  return wrap_diff_deg(az_a_deg, az_b_deg) * std::cos(el_deg * kRadPerDeg) * kArcsecPerDeg;
}

void Stats::add(double value, std::string_view label) {
  ++count_;
  sum_ += value;
  sum_sq_ += value * value;
  // A NaN or infinity is the worst possible case: it must show up, never hide behind max().
  if (count_ == 1 || !(std::abs(value) <= max_abs_)) {
    max_abs_ = std::isfinite(value) ? std::abs(value) : std::numeric_limits<double>::infinity();
    worst_label_ = std::string(label);
  }
}

double Stats::rms() const {
  return count_ == 0 ? 0.0 : std::sqrt(sum_sq_ / static_cast<double>(count_));
}

double Stats::mean() const { return count_ == 0 ? 0.0 : sum_ / static_cast<double>(count_); }

std::string format_summary(std::string_view title, std::span<const SummaryRow> rows) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << "\n== " << title << " ==\n";
  out << std::left << std::setw(34) << "quantity" << std::setw(8) << "unit" << std::right
      << std::setw(6) << "n" << std::setw(13) << "max|diff|" << std::setw(13) << "rms"
      << std::setw(13) << "mean" << std::setw(11) << "bar"
      << "  result\n";
  for (const SummaryRow& row : rows) {
    out << std::left << std::setw(34) << row.quantity << std::setw(8) << row.unit << std::right
        << std::setw(6) << row.stats.count() << std::setw(13) << std::setprecision(4)
        << row.stats.max_abs() << std::setw(13) << row.stats.rms() << std::setw(13)
        << row.stats.mean() << std::setw(11);
    if (row.bar) {
      out << *row.bar << "  " << (row.stats.max_abs() <= *row.bar ? "pass" : "FAIL");
    } else {
      out << "-"
          << "  report";
    }
    out << "   worst: " << row.stats.worst_label() << "\n";
  }
  return out.str();
}

std::optional<double> poly_fit_slope_at_zero(std::span<const double> t, std::span<const double> y,
                                             int degree) {
  if (degree < 1 || degree > 5 || t.size() != y.size() ||
      t.size() < static_cast<std::size_t>(degree) + 1) {
    return std::nullopt;
  }
  const auto m = static_cast<std::size_t>(degree) + 1;
  // Rescale t to [−1, 1] and centre y, then solve the normal equations by Gaussian elimination
  // with partial pivoting; for ≤ 6 unknowns on [−1, 1] that is well conditioned enough.
  double t_scale = 0.0;
  for (const double ti : t) t_scale = std::max(t_scale, std::abs(ti));
  double y_mean = 0.0;
  for (const double yi : y) y_mean += yi;
  y_mean /= static_cast<double>(y.size());
  if (t_scale == 0.0) return std::nullopt;

  std::array<std::array<double, 7>, 6> a{};  // augmented matrix [N | b]
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double u = t[i] / t_scale;
    std::array<double, 6> powers{};
    powers[0] = 1.0;
    for (std::size_t k = 1; k < m; ++k) powers[k] = powers[k - 1] * u;
    for (std::size_t r = 0; r < m; ++r) {
      for (std::size_t c = 0; c < m; ++c) a[r][c] += powers[r] * powers[c];
      a[r][m] += powers[r] * (y[i] - y_mean);
    }
  }
  for (std::size_t col = 0; col < m; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < m; ++r) {
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    }
    if (std::abs(a[pivot][col]) < 1e-300) return std::nullopt;
    std::swap(a[col], a[pivot]);
    for (std::size_t r = 0; r < m; ++r) {
      if (r == col) continue;
      const double f = a[r][col] / a[col][col];
      for (std::size_t c = col; c <= m; ++c) a[r][c] -= f * a[col][c];
    }
  }
  // Coefficient of u¹ is the slope in u; d/dt = (d/du) / t_scale.
  return a[1][m] / a[1][1] / t_scale;
}

}  // namespace azt::oracle
