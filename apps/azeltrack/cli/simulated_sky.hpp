#pragma once
// The simulated sky of the calibration scenarios (docs/calibration.md "In simulation"): the
// ephemeris, the start instant, and every source the simulated receiver hears (sky_emitters)
// as a track from that instant, with the station and receiver of the configuration.

#include <memory>
#include <string>
#include <vector>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/sim/calibration_sim.hpp"
#include "config/sim_config.hpp"
#include "station/sky_emitters.hpp"

namespace azt::app {

struct SimulatedSky {
  std::unique_ptr<astro::Ephemeris> ephemeris;  ///< the tracks read it: keep it alive
  astro::UtcInstant start;
  sim::CalibrationSimSetup setup;
  std::vector<SkyEmitter> emitters;  ///< in the order of setup.sources
};

/// The sky from `from` (ISO 8601 UTC; empty: now) for `hours`. Throws UsageError on a bad
/// instant.
std::unique_ptr<SimulatedSky> simulated_sky(const SimConfig& config, const std::string& from,
                                            double hours);

/// The source named `name` (sun, moon, a catalogue key); throws UsageError naming the choices.
std::size_t source_index(const SimulatedSky& sky, const std::string& name);

}  // namespace azt::app
