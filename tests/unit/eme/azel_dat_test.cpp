// azel.dat as WSJT-X writes it (lib/astrosub.f90, format 1010), so the programs that read it
// by fixed columns read ours: the four lines, field widths, rounding, R/T, and the optional fifth
// (format 1020).
#include "azt/eme/azel_dat.hpp"

#include <gtest/gtest.h>

namespace azt::eme {
namespace {

TEST(AzelDat, WsjtxsFourLines) {
  AzelDat d;
  d.utc_s_of_day = 3600.0 * 23 + 60.0 * 4 + 5.7;
  d.moon_az_deg = 94.94;
  d.moon_el_deg = 9.87;
  d.sun_az_deg = 275.06;
  d.sun_el_deg = -12.34;
  d.freq_mhz = 144.12;
  d.dx_doppler_hz = 36.4;
  d.dx_dfdt_hz_min = -0.123;
  d.self_doppler_hz = -153.5;
  d.self_dfdt_hz_min = 1.5;
  EXPECT_EQ(azel_dat_text(d),
            "23:04:05, 94.9,  9.9,Moon\n"
            "23:04:05,275.1,-12.3,Sun\n"
            "23:04:05,  0.0,  0.0,Source\n"
            "  144,    36.0,   -0.12,  -154.0,    1.50,Doppler, R\n");
}

TEST(AzelDat, TransmittingASourceAndTheTopOfTheBands) {
  AzelDat d;
  d.utc_s_of_day = 59.999;
  d.source_az_deg = 359.96;  // rounds to 360.0, as WSJT-X's f5.1 does
  d.source_el_deg = 45.0;
  d.freq_mhz = 10368.1;
  d.self_doppler_hz = -25000.4;
  d.transmitting = true;
  const std::string text = azel_dat_text(d);
  EXPECT_NE(text.find("00:00:59,360.0, 45.0,Source\n"), std::string::npos) << text;
  EXPECT_NE(text.find("10368,     0.0,    0.00,-25000.0,    0.00,Doppler, T\n"), std::string::npos)
      << text;
  d.self_doppler_hz = 160000.0;  // 76 GHz receding: fits f8.1
  EXPECT_NE(azel_dat_text(d).find(",160000.0,"), std::string::npos);
}

TEST(AzelDat, EveryFieldKeepsItsColumnsWhereFortranWouldPrintStars) {
  AzelDat d;
  d.freq_mhz = 76032.1;
  d.self_doppler_hz = -160000.0;  // 76 GHz approaching: "-160000.0" is nine characters
  d.dx_doppler_hz = 2.0e6;
  d.self_dfdt_hz_min = -12345.678;
  d.dx_dfdt_hz_min = 123456.0;
  const std::string text = azel_dat_text(d);
  EXPECT_NE(text.find("76032,999999.9,99999.99,-99999.9,-9999.99,Doppler, R\n"), std::string::npos)
      << text;
}

TEST(AzelDat, TheFifthLineOnlyWhenAsked) {
  AzelDat d;
  EXPECT_EQ(azel_dat_text(d).find("Pol"), std::string::npos);
  d.pol = AzelDat::PolLine{-37.46, 4.02, -1.26, 12.31, 0.0};
  const std::string text = azel_dat_text(d);
  const std::string fifth = "   -37.5,     4.0,    -1.3,    12.3,     0.0,Pol\n";
  ASSERT_GE(text.size(), fifth.size());
  EXPECT_EQ(text.substr(text.size() - fifth.size()), fifth) << text;
}

}  // namespace
}  // namespace azt::eme
