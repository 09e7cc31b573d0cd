#pragma once
// Where the polarisation axis should turn a linear feed (docs/eme.md, "Polarisation axis"): the
// angle for each mode, and the mount angle within the axis's travel that gives it. Pure.
//
// The angle convention. The pol axis angle is the feed's angle from level, in degrees: 0 is the
// polarisation WSJT-X calls level at this station (its Astronomical Data window's Dpol is the
// turn from there: WSJTX/wsjtx lib/astro.f90, eme/polarisation.hpp), positive clockwise looking
// from behind the antenna towards the Moon, as WSJT-X's Dpol is. A linear polarisation turned by
// 180° is the same polarisation, so a feed angle is folded to (−90, 90] and the axis may reach it
// at any angle 180° away (plan_pol_mount).
//
// The modes. Off: no target, the axis holds and its drive is off. Fixed: `fixed_deg`. Manual:
// the operator's angle. Self (our own echoes): the spatial offset to ourselves is zero, so the
// target is `self_offset_deg`, the Faraday correction the operator peaked. DX: Dpol to the DX
// station plus `dx_offset_deg`, the receive optimum (the Faraday correction peaked on the DX
// signal). Split: receiving as DX; transmitting, the angle the DX station receives best, by
// G3SEK's rule (KL7WE's method, "Make More 432 MHz EME Contacts by Polarization Rotation",
// DUBUS 3/1996, http://www.ifwtech.co.uk/g3sek/eme/pol3.htm): TX = 2·S − RX (mod 180°), S the
// spatial offset (Dpol). With RX = S + dx_offset that is TX = S − dx_offset: Faraday rotation
// turns the same way on both paths in the sky's frame, so it is undone on transmit by turning the
// other way from the spatial offset. G3SEK's cases: Faraday 0° or 90° gives TX = RX, 45° gives
// 90° between them.
//
// `hold_while_keyed`: while the transmitter is keyed the axis gets no new target in any mode
// (it holds where it stands), for feeds whose motor or rotary joint must not move under power.

#include <cstdint>
#include <optional>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::control {

enum class PolMode : std::uint8_t { Off, Fixed, Manual, Self, Dx, Split };

/// "off", "fixed", "manual", "self", "dx", "split": the names of `[pol] mode`.
std::string_view to_string(PolMode mode);
/// The mode of one of the names above (exactly); an error that lists them otherwise.
Result<PolMode> parse_pol_mode(std::string_view text);

struct PolSettings {
  PolMode mode = PolMode::Off;
  double fixed_deg = 0.0;        ///< Fixed: the feed angle
  double self_offset_deg = 0.0;  ///< Self: the Faraday correction peaked on our own echo
  double dx_offset_deg = 0.0;    ///< DX and Split: the correction peaked on the DX signal
  bool hold_while_keyed = false;
};

/// What changes tick by tick.
struct PolInputs {
  std::optional<double> manual_deg;          ///< Manual: the operator's angle, if given yet
  std::optional<double> spatial_offset_deg;  ///< Dpol(own, DX); nullopt without a DX grid
  bool transmitting = false;                 ///< PTT, or WSJT-X's Transmitting
};

/// A feed angle folded to (−90, 90].
double fold_linear_deg(double deg);

/// The feed angle (folded) for this tick, or nullopt: no new target (Off, keyed with
/// hold_while_keyed, Manual without an angle, DX or Split without a spatial offset).
std::optional<double> pol_feed_deg(const PolSettings& settings, const PolInputs& inputs);

/// The pol axis's mechanical travel, mount degrees (the feed angle the sensor reads).
struct PolTravel {
  double min_deg = -95.0;
  double max_deg = 95.0;
  /// Finite, min < max, and at least 180° wide: every linear polarisation is then reachable.
  static Result<PolTravel> make(double min_deg, double max_deg);
};

/// The mount angle for `feed_deg`: among feed + k·180° inside the travel, the one nearest
/// `present_mount_deg`. A travel narrower than 180° (not made by PolTravel::make) may hold none:
/// then the nearer end, never beyond it.
double plan_pol_mount(double present_mount_deg, double feed_deg, const PolTravel& travel);

}  // namespace azt::control
