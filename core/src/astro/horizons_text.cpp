#include "horizons_text.hpp"

#include <algorithm>
#include <string>

#include "azt/util/format_number.hpp"
#include "azt/util/parse_number.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::astro::horizons_text {

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

Error line_error(std::string_view table, std::size_t index, std::string_view line,
                 std::string_view why) {
  std::string shown(trim(line).substr(0, 100));
  return fail(std::string(table) + ", line " + std::to_string(index + 1) + " (" + shown +
              "): " + std::string(why));
}

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

std::string without_source_note(std::string_view value) {
  return std::string(trim(value.substr(0, value.find('{'))));
}

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

Result<std::vector<double>> offsets_from_first(const std::vector<JulianDate>& times,
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

}  // namespace azt::astro::horizons_text
