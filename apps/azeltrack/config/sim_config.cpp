#include "config/sim_config.hpp"

#include <algorithm>
#include <cstdint>

#include "azt/proto/hub_frame.hpp"
#include "azt/util/format_number.hpp"
#include "config/config_file.hpp"
#include "config/pointing_config.hpp"
#include "config/station_setup_config.hpp"

namespace azt::app {
namespace {

/// The simulated plant of one axis: the mount's rate and encoders ([mount.az]), with its own
/// imperfections (by default the ones the controller is told of) and start angle and stops.
sim::AxisParams read_plant(const ConfigSection& s, const AxisMount& mount,
                           const sim::AxisParams& defaults) {
  sim::AxisParams p = defaults;
  p.max_rate_deg_s = mount.max_rate_deg_s;
  p.encoder_bits = mount.encoder_bits;
  p.time_constant_s = s.number("time_constant_s").value_or(mount.time_constant_s);
  p.backlash_deg = s.number("backlash_deg").value_or(mount.backlash_deg);
  p.stiction_duty = s.number("stiction_duty").value_or(mount.min_duty);
  p.min_deg = s.number("min_deg").value_or(p.min_deg);
  p.max_deg = s.number("max_deg").value_or(p.max_deg);
  // Unless given, the antenna starts where the travel allows (an elevation limit above 0°).
  const bool travel = p.min_deg < p.max_deg;  // else validate() says so
  p.start_deg = s.number("start_deg")
                    .value_or(travel ? std::clamp(p.start_deg, p.min_deg, p.max_deg) : p.start_deg);
  if (auto ok = p.validate(); !ok) {
    // "start_deg must be within …": the key the message begins with is the one at fault.
    const std::string& message = ok.error().message;
    const auto space = message.find(' ');
    s.fail(message.substr(0, space), message.substr(space + 1));
  }
  return p;
}

/// `fault = "frozen_shaft" | "reversed_motor" | "encoder_offset"` starting `fault_at_s` seconds
/// after the start (`fault_counts` for the offset): a plant fault to rehearse, or to test the
/// station's refusals against.
void read_plant_fault(const ConfigSection& s, bool azimuth, sim::PlantSetup& plant) {
  const auto kind = s.text("fault");
  if (!kind) return;
  sim::AxisFault fault;
  if (*kind == "reversed_motor") {
    fault.kind = sim::AxisFaultKind::ReversedMotor;
  } else if (*kind == "encoder_offset") {
    fault.kind = sim::AxisFaultKind::EncoderOffset;
    const std::int64_t counts = s.integer("fault_counts").value_or(100);
    if (counts < -65535 || counts > 65535) s.fail("fault_counts", "must be -65535 to 65535");
    fault.counts = static_cast<std::int32_t>(counts);
  } else if (*kind != "frozen_shaft") {
    s.fail("fault", "must be \"frozen_shaft\", \"reversed_motor\" or \"encoder_offset\"");
  }
  const double at_s = s.number("fault_at_s").value_or(0.0);
  if (!(at_s >= 0.0)) s.fail("fault_at_s", "must be 0 or more seconds");
  plant.faults.push_back(sim::ScheduledFault{at_s, azimuth, fault});
}

void read_link(const ConfigSection& s, sim::PlantSetup& plant) {
  const std::string version = s.text("frame_version").value_or("crc8");
  if (version == "seed") {
    plant.frame_version = proto::HubFrameVersion::Seed;
  } else if (version != "crc8") {
    s.fail("frame_version", "must be \"seed\" or \"crc8\"");
  }
  plant.link.frame_loss = s.number("frame_loss").value_or(0.0);
  plant.link.byte_corruption = s.number("byte_corruption").value_or(0.0);
  for (double p : {plant.link.frame_loss, plant.link.byte_corruption}) {
    if (p < 0.0 || p > 1.0) s.fail("frame_loss", "probabilities must be 0 to 1");
  }
  if (auto seed = s.integer("seed")) plant.seed = static_cast<std::uint64_t>(*seed);
}

}  // namespace

sim::PlantSetup plant_setup_from(const ConfigFile& file, const MountConfig& mount,
                                 const control::StationSetup& station) {
  sim::PlantSetup plant;
  const ConfigSection sim_section =
      file.section("sim", {"az", "el", "frame_version", "frame_loss", "byte_corruption", "seed",
                           "hub", "hub_firmware", "mount_errors", "receiver"});
  const std::initializer_list<std::string_view> plant_keys = {
      "time_constant_s", "backlash_deg", "stiction_duty", "start_deg",   "min_deg",
      "max_deg",         "fault",        "fault_at_s",    "fault_counts"};
  // The plants' end stops are the travel's unless given.
  sim::AxisParams az_defaults;
  az_defaults.min_deg = station.az_range.min_deg;
  az_defaults.max_deg = station.az_range.max_deg;
  sim::AxisParams el_defaults;
  el_defaults.min_deg = station.el_range.min_deg;
  el_defaults.max_deg = station.el_range.max_deg;
  plant.az = read_plant(sim_section.child("az", plant_keys), mount.az, az_defaults);
  plant.el = read_plant(sim_section.child("el", plant_keys), mount.el, el_defaults);
  read_plant_fault(sim_section.child("az", plant_keys), true, plant);
  read_plant_fault(sim_section.child("el", plant_keys), false, plant);
  read_link(sim_section, plant);
  plant.pointing_errors = mount_errors_from(sim_section);
  return plant;
}

SimHubConfig sim_hub_from(const ConfigFile& file) {
  const ConfigSection s =
      file.section("sim", {"az", "el", "frame_version", "frame_loss", "byte_corruption", "seed",
                           "hub", "hub_firmware", "mount_errors", "receiver"});
  SimHubConfig hub;
  const std::string kind = s.text("hub").value_or("model");
  if (kind != "model" && kind != "firmware") s.fail("hub", "must be \"model\" or \"firmware\"");
  hub.firmware = kind == "firmware";
  hub.elf = s.text("hub_firmware").value_or("");
  return hub;
}

SimReceiverConfig sim_receiver_from(const ConfigFile& file) {
  const ConfigSection s =
      file.section("sim", {"az", "el", "frame_version", "frame_loss", "byte_corruption", "seed",
                           "hub", "hub_firmware", "mount_errors", "receiver"})
          .child("receiver", {"beamwidth_deg", "tsys_k", "noise_db", "rate_hz", "dish_m",
                              "efficiency", "sun_k", "moon_k", "flux_mhz", "seed"});
  SimReceiverConfig c;
  sim::ReceiverSetup& r = c.receiver;
  const auto positive = [&s](std::string_view key, double fallback, double max) {
    const double v = s.number(key).value_or(fallback);
    if (!(v > 0.0 && v <= max)) s.fail(key, "must be above 0 and at most " + format_number(max));
    return v;
  };
  r.beamwidth_deg = positive("beamwidth_deg", r.beamwidth_deg, 30.0);
  r.tsys_k = positive("tsys_k", r.tsys_k, 1e5);
  r.rate_hz = positive("rate_hz", r.rate_hz, 100.0);
  r.dish_m = positive("dish_m", r.dish_m, 100.0);
  r.efficiency = positive("efficiency", r.efficiency, 1.0);
  c.sun_k = positive("sun_k", c.sun_k, 1e8);
  c.moon_k = positive("moon_k", c.moon_k, 1e4);
  r.noise_db = s.number("noise_db").value_or(r.noise_db);
  if (!(r.noise_db >= 0.0 && r.noise_db <= 10.0)) s.fail("noise_db", "must be 0 to 10");
  if (auto seed = s.integer("seed")) r.seed = static_cast<std::uint64_t>(*seed);
  c.flux_mhz = s.integer("flux_mhz").value_or(c.flux_mhz);
  if (c.flux_mhz != 1296 && c.flux_mhz != 2304 && c.flux_mhz != 10368) {
    s.fail("flux_mhz", "must be 1296, 2304 or 10368 (the catalogue's flux densities)");
  }
  return c;
}

SimConfig sim_config_from(const ConfigFile& file) {
  SimConfig config;
  config.sky = sky_config_from(file);
  config.mount = mount_config_from(file);
  config.setup.station = station_setup_from(file, config.mount);
  config.setup.plant = plant_setup_from(file, config.mount, config.setup.station);
  config.hub = sim_hub_from(file);
  config.receiver = sim_receiver_from(file);
  return config;
}

}  // namespace azt::app
