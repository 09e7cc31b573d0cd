#pragma once
// What the polarisation axis follows through a simulated Moon pass (docs/eme.md, "Polarisation
// axis"): the spatial offset between our station and the DX station (Dpol, WSJT-X's: the core's
// eme/polarisation.hpp on the sky engine's Moon, as the daemon computes it for its EME data), a
// push-to-talk sequence, and the feed angle control/pol_target.hpp chooses from them.

#include <functional>
#include <optional>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/observer.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/control/pol_target.hpp"
#include "azt/sim/station_sim.hpp"

namespace azt::sim {

struct PolTrackSetup {
  const astro::Ephemeris* ephemeris = nullptr;  ///< must outlive the track
  astro::Observer own;
  std::optional<astro::Observer> dx;  ///< nullopt: no DX station (DX and Split modes hold)
  astro::UtcInstant start;
  double dut1_s = 0.0;
  const astro::LeapSecondTable* leap_table = nullptr;  ///< must outlive the track
  control::PolSettings settings;
  /// Alternate receive and transmit periods of this length, receiving first (WSJT-X's T/R
  /// periods: 60 s for JT65 and Q65-60); 0: never transmitting.
  double ptt_period_s = 0.0;
};

/// Whether the station transmits `t_s` seconds after the start: the second, fourth, … period.
bool transmitting_at(double t_s, double ptt_period_s);

/// Dpol (degrees, (−90, 90]) at `t_s` seconds after the start, or nullopt without a DX station or
/// where the sky engine cannot compute the Moon. Computed every 10 s and interpolated between (it
/// turns at hundredths of a degree a second away from the zenith).
std::function<std::optional<double>(double t_s)> make_dpol_track(const PolTrackSetup& setup);

/// The feed angle for each instant: pol_feed_deg of the settings, Dpol and the PTT sequence.
PolTrack make_pol_track(const PolTrackSetup& setup);

}  // namespace azt::sim
