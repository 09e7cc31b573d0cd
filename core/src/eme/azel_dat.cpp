#include "azt/eme/azel_dat.hpp"

#include <cmath>
#include <cstdio>

namespace azt::eme {
namespace {

constexpr int kSecondsPerDay = 86400;

std::string clock_text(double utc_s_of_day) {
  const int s = static_cast<int>(std::floor(utc_s_of_day)) % kSecondsPerDay;
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d:%02d:%02d", s / 3600, s / 60 % 60, s % 60);
  return buf;
}

std::string place_line(const std::string& clock, double az, double el, const char* name) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s,%5.1f,%5.1f,%s\n", clock.c_str(), az, el, name);
  return buf;
}

}  // namespace

std::string azel_dat_text(const AzelDat& d) {
  const std::string clock = clock_text(d.utc_s_of_day);
  char doppler[128];
  std::snprintf(doppler, sizeof doppler, "%5d,%8.1f,%8.2f,%8.1f,%8.2f,Doppler, %c\n",
                static_cast<int>(d.freq_mhz), std::round(d.dx_doppler_hz), d.dx_dfdt_hz_min,
                std::round(d.self_doppler_hz), d.self_dfdt_hz_min, d.transmitting ? 'T' : 'R');
  return place_line(clock, d.moon_az_deg, d.moon_el_deg, "Moon") +
         place_line(clock, d.sun_az_deg, d.sun_el_deg, "Sun") +
         place_line(clock, d.source_az_deg, d.source_el_deg, "Source") + doppler;
}

}  // namespace azt::eme
