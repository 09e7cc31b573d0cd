#include "cli/simulated_sky.hpp"

#include "azt/sim/sky_track.hpp"
#include "common/sky_setup.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

sim::SkyTrack track_of(const SimConfig& c, const SimulatedSky& sky, const astro::Target& target) {
  sim::SkyTrackSetup t;
  t.ephemeris = sky.ephemeris.get();
  t.target = target;
  t.observer = c.sky.settings.observer;
  t.atmosphere = c.sky.settings.atmosphere;
  t.start = sky.start;
  t.dut1_s = c.sky.settings.dut1_s;
  t.leap_table = &leap_table();
  return sim::make_sky_track(t);
}

}  // namespace

std::unique_ptr<SimulatedSky> simulated_sky(const SimConfig& config, const std::string& from,
                                            double hours) {
  auto sky = std::make_unique<SimulatedSky>();
  sky->ephemeris = open_ephemeris(config.sky.settings.ephemeris);
  sky->start = utc_now();
  if (!from.empty()) {
    auto parsed = astro::parse_iso8601_utc(from);
    if (!parsed) throw UsageError("--from: " + parsed.error().message);
    sky->start = *parsed;
  }
  time_scales_at(sky->start, config.sky.settings.dut1_s);  // validates the instant
  sky->setup.station = config.setup;
  sky->setup.receiver = config.receiver.receiver;
  sky->setup.duration_s = hours * 3600.0;
  sky->emitters = sky_emitters(config.receiver);
  for (const SkyEmitter& e : sky->emitters) {
    sky->setup.sources.push_back({e.name, track_of(config, *sky, e.target), e.peak_k, e.size_deg});
  }
  return sky;
}

std::size_t source_index(const SimulatedSky& sky, const std::string& name) {
  for (std::size_t i = 0; i < sky.emitters.size(); ++i) {
    if (sky.emitters[i].name == name) return i;
  }
  throw UsageError("--source must be sun, moon or a catalogue source with a flux at the band");
}

}  // namespace azt::app
