#include "azt/radio/eme_doppler_modes.hpp"

#include <array>
#include <cmath>
#include <utility>

namespace azt::radio {
namespace {

constexpr std::array<std::pair<EmeDopplerMode, std::string_view>, 6> kModeNames = {{
    {EmeDopplerMode::None, "off"},
    {EmeDopplerMode::FullDx, "dx"},
    {EmeDopplerMode::ConstantOnMoon, "constant"},
    {EmeDopplerMode::OwnEcho, "self"},
    {EmeDopplerMode::OnDxEcho, "on_dx"},
    {EmeDopplerMode::CallDx, "call_dx"},
}};

/// WSJT-X's correction without the Tx shift; `dx` is 0 for the modes that do not use it.
EmeCorrection unshifted(EmeDopplerMode mode, double self, double dx) {
  switch (mode) {
    case EmeDopplerMode::None:
      return {0.0, 0.0};
    case EmeDopplerMode::FullDx:
      return {dx, -dx};
    case EmeDopplerMode::ConstantOnMoon:
      return {self / 2.0, -self / 2.0};
    case EmeDopplerMode::OwnEcho:
      return {self, 0.0};
    case EmeDopplerMode::OnDxEcho:
      return {dx, dx - self};
    case EmeDopplerMode::CallDx:
      return {0.0, -self};
  }
  return {0.0, 0.0};
}

}  // namespace

bool needs_dx(EmeDopplerMode mode) {
  return mode == EmeDopplerMode::FullDx || mode == EmeDopplerMode::OnDxEcho;
}

Result<EmeCorrection> eme_correction(EmeDopplerMode mode, const EchoDoppler& doppler,
                                     double tx_shift_hz) {
  if (needs_dx(mode) && !doppler.dx_echo_hz) {
    return fail(std::string(eme_mode_name(mode)) + " Doppler needs the DX station's locator");
  }
  EmeCorrection out = unshifted(mode, doppler.self_echo_hz, doppler.dx_echo_hz.value_or(0.0));
  out.tx_hz += tx_shift_hz;
  return out;
}

std::string_view eme_mode_name(EmeDopplerMode mode) {
  for (const auto& [m, name] : kModeNames) {
    if (m == mode) return name;
  }
  return "off";
}

std::optional<EmeDopplerMode> parse_eme_mode(std::string_view name) {
  for (const auto& [mode, text] : kModeNames) {
    if (text == name) return mode;
  }
  return std::nullopt;
}

TxPeriod next_tx_period(double now_unix_s, double tr_period_s) {
  const double base_s = std::floor(now_unix_s) + 2.0;
  const double index = std::floor(base_s / tr_period_s);
  return {static_cast<std::int64_t>(index), index * tr_period_s + 0.5 * tr_period_s};
}

std::optional<TxPeriod> TxOncePerPeriod::due(double now_unix_s, double tr_period_s,
                                             bool transmitting) const {
  if (transmitting || !(tr_period_s > 0.0)) return std::nullopt;
  const TxPeriod next = next_tx_period(now_unix_s, tr_period_s);
  if (last_index_ == next.index) return std::nullopt;
  return next;
}

}  // namespace azt::radio
