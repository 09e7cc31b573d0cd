#pragma once

#include <memory>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/observer.hpp"
#include "azt/astro/refraction.hpp"
#include "azt/astro/target.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/sim/station_sim.hpp"

namespace azt::sim {

/// What a SkyTrack needs to compute a target's apparent (refracted) az/el.
struct SkyTrackSetup {
  const astro::Ephemeris* ephemeris = nullptr;  ///< must outlive the track
  astro::Target target;
  astro::Observer observer;
  astro::Atmosphere atmosphere;
  astro::UtcInstant start;
  double dut1_s = 0.0;
  const astro::LeapSecondTable* leap_table = nullptr;
};

/// A SkyTrack over the real sky engine, evaluated once per whole second and interpolated
/// linearly between (the Moon moves 0.004°/s: the interpolation error is below 1e-8°), so a
/// simulated hour costs 3600 sky evaluations instead of 72 000. Instants the engine cannot
/// compute yield nullopt.
SkyTrack make_sky_track(const SkyTrackSetup& setup);

}  // namespace azt::sim
