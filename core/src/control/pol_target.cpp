#include "azt/control/pol_target.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace azt::control {
namespace {

constexpr std::array kModes{PolMode::Off,  PolMode::Fixed, PolMode::Manual,
                            PolMode::Self, PolMode::Dx,    PolMode::Split};

/// The DX receive optimum: the spatial offset and the Faraday correction peaked on the DX.
std::optional<double> dx_rx_deg(const PolSettings& s, const PolInputs& in) {
  if (!in.spatial_offset_deg) return std::nullopt;
  return *in.spatial_offset_deg + s.dx_offset_deg;
}

/// G3SEK's rule (pol_target.hpp): TX = 2·S − RX.
std::optional<double> dx_tx_deg(const PolSettings& s, const PolInputs& in) {
  const auto rx = dx_rx_deg(s, in);
  if (!rx) return std::nullopt;
  return 2.0 * *in.spatial_offset_deg - *rx;
}

std::optional<double> unfolded_target_deg(const PolSettings& s, const PolInputs& in) {
  switch (s.mode) {
    case PolMode::Off:
      return std::nullopt;
    case PolMode::Fixed:
      return s.fixed_deg;
    case PolMode::Manual:
      return in.manual_deg;
    case PolMode::Self:
      return s.self_offset_deg;
    case PolMode::Dx:
      return dx_rx_deg(s, in);
    case PolMode::Split:
      return in.transmitting ? dx_tx_deg(s, in) : dx_rx_deg(s, in);
  }
  return std::nullopt;
}

}  // namespace

std::string_view to_string(PolMode mode) {
  switch (mode) {
    case PolMode::Off:
      return "off";
    case PolMode::Fixed:
      return "fixed";
    case PolMode::Manual:
      return "manual";
    case PolMode::Self:
      return "self";
    case PolMode::Dx:
      return "dx";
    case PolMode::Split:
      return "split";
  }
  return "?";
}

Result<PolMode> parse_pol_mode(std::string_view text) {
  for (const PolMode mode : kModes) {
    if (text == to_string(mode)) return mode;
  }
  return fail("unknown polarisation mode \"" + std::string(text) +
              "\" (off, fixed, manual, self, dx or split)");
}

double fold_linear_deg(double deg) {
  double d = std::fmod(deg, 180.0);  // (−180, 180)
  if (d <= -90.0) d += 180.0;
  if (d > 90.0) d -= 180.0;
  return d;
}

std::optional<double> pol_feed_deg(const PolSettings& settings, const PolInputs& inputs) {
  if (settings.hold_while_keyed && inputs.transmitting) return std::nullopt;
  const auto target = unfolded_target_deg(settings, inputs);
  if (!target || !std::isfinite(*target)) return std::nullopt;
  return fold_linear_deg(*target);
}

Result<PolTravel> PolTravel::make(double min_deg, double max_deg) {
  if (!std::isfinite(min_deg) || !std::isfinite(max_deg)) {
    return fail("the polarisation travel must be finite");
  }
  if (max_deg - min_deg < 180.0) {
    return fail(
        "the polarisation travel (min_deg to max_deg) must span at least 180 degrees, "
        "or some linear polarisations cannot be reached");
  }
  return PolTravel{min_deg, max_deg};
}

double plan_pol_mount(double present_mount_deg, double feed_deg, const PolTravel& travel) {
  // The equivalent angles feed + k·180 from the one at or above the travel's start upwards.
  const double first = feed_deg + 180.0 * std::ceil((travel.min_deg - feed_deg) / 180.0);
  std::optional<double> best;
  // Bounded: a travel of any sense spans a few half turns, and a NaN must not loop forever.
  constexpr int kMaxHalfTurns = 16;
  for (int k = 0; k < kMaxHalfTurns; ++k) {
    const double candidate = first + 180.0 * k;
    if (!(candidate <= travel.max_deg)) break;
    if (!best || std::fabs(candidate - present_mount_deg) < std::fabs(*best - present_mount_deg)) {
      best = candidate;
    }
  }
  if (best) return *best;
  // None inside: the end nearer the wanted angle, never beyond the travel.
  const double folded = fold_linear_deg(feed_deg);
  return std::clamp(folded, travel.min_deg, travel.max_deg);
}

}  // namespace azt::control
