#pragma once
// azel.dat, the file WSJT-X writes once a second and Doppler and rotator programs read
// (WSJTX/wsjtx lib/astrosub.f90, format 1010): azeltrack writes the same so those programs get
// its numbers (docs/eme.md). Four lines:
//   HH:MM:SS,AAA.A,EE.E,Moon
//   HH:MM:SS,AAA.A,EE.E,Sun
//   HH:MM:SS,AAA.A,EE.E,Source
//   FFFFF,DDDDDD.D,RRRRR.RR,SSSSSS.S,TTTTT.TT,Doppler, R
// Az/El to 0.1° (WSJT-X's f5.1: readers parse fixed widths), the frequency in whole MHz, the DX
// and self echo Doppler rounded to whole Hz and their rates in Hz per minute, R or T for receive
// or transmit. WSJT-X's optional fifth line (written when its AzElExtraLines setting is on):
//   DDDDDD.D,MMMMMM.M,GGGGGG.G,WWWWWW.W,XXXXXX.X,Pol
// Dpol (between the two stations), MNR and Dgrd (dB), the self and DX echo widths (Hz), each f8.1.
// Every field keeps its fixed width: where WSJT-X's Fortran would print asterisks (an echo
// Doppler below −100 kHz, at 47 GHz and up), the value is held at the largest the column shows.

#include <optional>
#include <string>

namespace azt::eme {

struct AzelDat {
  double utc_s_of_day = 0.0;  ///< seconds since 00:00 UTC
  double moon_az_deg = 0.0;
  double moon_el_deg = 0.0;
  double sun_az_deg = 0.0;
  double sun_el_deg = 0.0;
  double source_az_deg = 0.0;  ///< the tracked radio source; 0, 0 (as WSJT-X) when none
  double source_el_deg = 0.0;
  double freq_mhz = 0.0;
  double dx_doppler_hz = 0.0;  ///< the DX echo (own QTH to the Moon to the DX); 0 without a DX
  double dx_dfdt_hz_min = 0.0;
  double self_doppler_hz = 0.0;
  double self_dfdt_hz_min = 0.0;
  bool transmitting = false;
  /// WSJT-X's fifth line, when wanted.
  struct PolLine {
    double dpol_deg = 0.0;  ///< 0 without a DX (as WSJT-X)
    double mnr_db = 0.0;
    double dgrd_db = 0.0;
    double width_hz = 0.0;
    double dx_width_hz = 0.0;  ///< 0 without a DX
  };
  std::optional<PolLine> pol;
};

std::string azel_dat_text(const AzelDat& d);

}  // namespace azt::eme
