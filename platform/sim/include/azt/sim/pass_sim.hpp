#pragma once
// Satellite passes on the simulated plant (docs/satellites.md): synthetic pass geometry for
// tests that must cover every kind of pass (north-crossing, overhead, grazing) without an
// orbit library, and the run of the real StationController through a planned pass.

#include <cstdint>
#include <vector>

#include "azt/sim/station_sim.hpp"
#include "azt/track/pass_plan.hpp"

namespace azt::sim {

/// A circular orbit over a spherical Earth seen from one site: the ground track passes
/// `offset_deg` of arc from the site (0: overhead), nearest it at azimuth `nearest_az_deg`, and
/// crosses it in the direction `+90°` from there (`clockwise`) or `−90°`.
struct SyntheticPass {
  double altitude_km = 500.0;
  double offset_deg = 5.0;
  double nearest_az_deg = 0.0;
  bool clockwise = true;
  double step_s = 1.0;
};

/// The pass above the horizon (el ≥ 0), sampled every step_s; empty if it never rises.
std::vector<track::SkyPoint> synthetic_pass(const SyntheticPass& p);
/// The highest elevation of such a pass (closed form).
double synthetic_max_el_deg(double altitude_km, double offset_deg);

/// The mount a station setup describes: its travel and its plants' full-speed rates.
track::MountGeometry mount_geometry(const StationSimSetup& setup);

struct PassSimResult {
  bool flip = false;
  double max_error_deg = 0.0;  ///< beam to satellite, from AOS to LOS
  double rms_error_deg = 0.0;
  /// The worst error beyond what the plan itself accepts (its keyhole): what the plant adds.
  double max_excess_deg = 0.0;
  double az_travel_deg = 0.0;  ///< the shaft, from AOS to LOS
  double pass_span_deg = 0.0;  ///< azimuth the planned path must sweep (unwrapped, total)
  int unwinds = 0;  ///< demand jumps of 180° or more between ticks (re-planning mid-pass)
  /// The time the beam was further than the mount's loss_error_deg from the satellite.
  double loss_s = 0.0;
  /// What the plan reported before AOS: its own worst error and lost time.
  double planned_max_error_deg = 0.0;
  double planned_loss_s = 0.0;
  std::vector<std::string> faults;
};

/// Plans the pass for a mount standing at `start` (mount angles), pre-positions for `prep_s`
/// before AOS, then tracks to LOS with the real controller on the plants of `setup` (their
/// rates, the travel of `mount`). Errors only for an unplannable pass.
Result<PassSimResult> simulate_pass(const std::vector<track::SkyPoint>& sky,
                                    const track::MountGeometry& mount, const StationSimSetup& setup,
                                    control::AzEl start, double prep_s);

}  // namespace azt::sim
