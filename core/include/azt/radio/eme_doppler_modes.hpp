#pragma once
// EME Doppler for a rig, WSJT-X's modes (WSJTX/wsjtx widgets/astro.cpp:192-240,
// Astro::astroUpdate), from the echo Doppler the core already computes at the dial frequency
// (azt/astro/sky.hpp):
//   self_echo_hz = self_echo_doppler_hz(f, ṙ) = −2·f·ṙ/c       (WSJT-X's m_dop00, "Dop_self")
//   dx_echo_hz   = dx_echo_doppler_hz(f, ṙ, ṙ_dx) = −f·(ṙ + ṙ_dx)/c   (WSJT-X's m_dop, "Dop_DX")
// ṙ is the Moon's range rate from our station, ṙ_dx from the DX station (positive receding).
// The rig is set as WSJT-X sets it (widgets/mainwindow.cpp:13831-13849):
//   rig RX = dial + rx_hz,   rig TX = dial + tx_hz
//
//   mode              rx_hz              tx_hz                      who hears what
//   None              0                  0                          no correction
//   FullDx            dx                 −dx                        DX's echo heard; DX hears us on
//   dial ConstantOnMoon    self/2             −self/2                    everyone's signal sits on
//   dial at the Moon OwnEcho           self               0                          our echo
//   heard; we send on dial OnDxEcho          dx                 dx − self                  we send
//   where our echo lands on the DX's echo CallDx            0                  −self our echo lands
//   on our dial
// (OnDxEcho: WSJT-X writes 2·(m_dop − m_dop00/2) − m_dop, the same sum.) WSJT-X's optional
// "Tx shift" is added to every tx_hz; its "reverse Doppler" switch and Echo mode's zero RX in
// FullDx are not modelled (docs/radio.md).
//
// Rigs that cannot change frequency while transmitting (WSJT-X's "Allow Tx frequency changes while
// transmitting" unticked, no_tx_QSY): the TX correction is computed once per T/R period for the
// middle of the next period and set before keying (astro.cpp:242-299); no TX retune while keyed.
// For None and OwnEcho the TX correction is constant, so there is nothing to plan.

#include <cstdint>
#include <optional>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::radio {

enum class EmeDopplerMode { None, FullDx, ConstantOnMoon, OwnEcho, OnDxEcho, CallDx };

/// The echo Doppler at the dial frequency, Hz. dx_echo_hz is absent without a DX locator.
struct EchoDoppler {
  double self_echo_hz = 0.0;
  std::optional<double> dx_echo_hz;
};

/// Corrections added to the dial (WSJT-X's correction.rx / correction.tx), Hz.
struct EmeCorrection {
  double rx_hz = 0.0;
  double tx_hz = 0.0;
};

/// Whether `mode` needs the DX echo Doppler (a DX locator).
bool needs_dx(EmeDopplerMode mode);

/// The corrections of `mode`. An error for FullDx and OnDxEcho without a DX locator (WSJT-X then
/// uses 0, which silently tunes for the self echo's half: better said than done wrong).
Result<EmeCorrection> eme_correction(EmeDopplerMode mode, const EchoDoppler& doppler,
                                     double tx_shift_hz = 0.0);

/// The configuration's word for a mode ("off", "dx", "constant", "self", "on_dx", "call_dx").
std::string_view eme_mode_name(EmeDopplerMode mode);
std::optional<EmeDopplerMode> parse_eme_mode(std::string_view name);

/// WSJT-X's instant for a no-TX-QSY correction: the middle of the T/R period that holds now + 2 s,
/// counted in whole seconds since the Unix epoch as WSJT-X does (astro.cpp:250-254: the 2 s make a
/// computation in the last seconds before a period start count for that period).
struct TxPeriod {
  std::int64_t index = 0;          ///< which period (seconds since the epoch / period)
  double doppler_at_unix_s = 0.0;  ///< compute the Doppler for this instant
};
TxPeriod next_tx_period(double now_unix_s, double tr_period_s);

/// Sets the TX correction once per T/R period, before keying (no_tx_QSY). Each tick: when due()
/// gives a period, compute the Doppler for its doppler_at_unix_s, write the TX, then call
/// written(period). Nothing is due while transmitting.
class TxOncePerPeriod {
 public:
  [[nodiscard]] std::optional<TxPeriod> due(double now_unix_s, double tr_period_s,
                                            bool transmitting) const;
  void written(const TxPeriod& period) { last_index_ = period.index; }
  void forget() { last_index_.reset(); }

 private:
  std::optional<std::int64_t> last_index_;
};

}  // namespace azt::radio
