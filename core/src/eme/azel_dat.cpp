#include "azt/eme/azel_dat.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace azt::eme {
namespace {

constexpr int kSecondsPerDay = 86400;

/// Right-aligned in `width` characters (wider when it must be), as Fortran's fixed formats.
std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

/// `value` with `decimals` digits after the point (Fortran fW.D), locale-free, held within what
/// `width` columns can show: readers cut the line at fixed columns.
std::string fixed(double value, int decimals, std::size_t width) {
  const double step = std::pow(10.0, -decimals);
  const double digits = static_cast<double>(width) - 1.0 - decimals;  // the point takes one
  const double largest = std::pow(10.0, digits) - step;
  const double smallest = -(std::pow(10.0, digits - 1.0) - step);  // the sign takes one
  const double shown = std::isfinite(value) ? std::clamp(value, smallest, largest) : 0.0;
  std::array<char, 64> buf{};
  const auto r =
      std::to_chars(buf.data(), buf.data() + buf.size(), shown, std::chars_format::fixed, decimals);
  return padded(std::string(buf.data(), r.ptr), width);
}

std::string two_digits(int v) { return (v < 10 ? "0" : "") + std::to_string(v); }

std::string clock_text(double utc_s_of_day) {
  const int s = static_cast<int>(std::floor(utc_s_of_day)) % kSecondsPerDay;
  return two_digits(s / 3600) + ":" + two_digits(s / 60 % 60) + ":" + two_digits(s % 60);
}

std::string place_line(const std::string& clock, double az, double el, const char* name) {
  return clock + "," + fixed(az, 1, 5) + "," + fixed(el, 1, 5) + "," + name + "\n";
}

/// WSJT-X's optional fifth line (lib/astrosub.f90, format 1020).
std::string pol_line(const AzelDat::PolLine& p) {
  return fixed(p.dpol_deg, 1, 8) + "," + fixed(p.mnr_db, 1, 8) + "," + fixed(p.dgrd_db, 1, 8) +
         "," + fixed(p.width_hz, 1, 8) + "," + fixed(p.dx_width_hz, 1, 8) + ",Pol\n";
}

}  // namespace

std::string azel_dat_text(const AzelDat& d) {
  const std::string clock = clock_text(d.utc_s_of_day);
  const std::string doppler =
      padded(std::to_string(static_cast<int>(d.freq_mhz)), 5) + "," +
      fixed(std::round(d.dx_doppler_hz), 1, 8) + "," + fixed(d.dx_dfdt_hz_min, 2, 8) + "," +
      fixed(std::round(d.self_doppler_hz), 1, 8) + "," + fixed(d.self_dfdt_hz_min, 2, 8) +
      ",Doppler, " + (d.transmitting ? "T" : "R") + "\n";
  return place_line(clock, d.moon_az_deg, d.moon_el_deg, "Moon") +
         place_line(clock, d.sun_az_deg, d.sun_el_deg, "Sun") +
         place_line(clock, d.source_az_deg, d.source_el_deg, "Source") + doppler +
         (d.pol ? pol_line(*d.pol) : std::string());
}

}  // namespace azt::eme
