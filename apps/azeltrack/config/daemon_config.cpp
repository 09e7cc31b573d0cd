#include "config/daemon_config.hpp"

#include <algorithm>
#include <cmath>

#include "common/horizon_mask_option.hpp"
#include "common/target_request.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/hardware_config.hpp"
#include "config/pol_config.hpp"
#include "config/sim_config.hpp"
#include "config/sky_config.hpp"
#include "config/token_label.hpp"

namespace azt::app {
namespace {

unsigned short read_port(const ConfigSection& s, std::string_view key, unsigned short fallback) {
  const auto port = s.integer(key);  // 0 to 65535 (the schema)
  return port ? static_cast<unsigned short>(*port) : fallback;
}

NetServerConfig read_net(const ConfigSection& s, NetServerConfig fallback) {
  fallback.bind = s.text("bind").value_or(fallback.bind);
  fallback.port = read_port(s, "port", fallback.port);
  return fallback;
}

std::vector<SerialServerConfig> read_serial(const ConfigFile& file) {
  std::vector<SerialServerConfig> out;
  for (const ConfigSection& s : file.section_array("serial")) {
    SerialServerConfig c;
    if (!s.has("protocol")) s.fail("protocol", "is required: " + choice_list(kSerialProtocols));
    c.protocol = s.choice("protocol", kSerialProtocols, c.protocol);
    c.device = s.text("device").value_or("");
    if (c.device.empty()) s.fail("device", "is required: \"pty:/path\" or a serial device path");
    c.baud = static_cast<unsigned>(s.integer("baud").value_or(9600));
    for (const auto& other : out) {
      if (other.device == c.device) s.fail("device", "is used by two [[serial]] servers");
    }
    out.push_back(std::move(c));
  }
  return out;
}

linux_os::HamlibConfig read_hamlib(const ConfigSection& s) {
  // The ranges are the schema's (config/schema_antenna_keys.cpp).
  linux_os::HamlibConfig h;
  h.model = static_cast<int>(s.integer("model").value_or(h.model));
  h.device = s.text("device").value_or("");
  h.baud = static_cast<int>(s.integer("baud").value_or(0));
  h.poll_s = s.number("poll_s").value_or(h.poll_s);
  h.min_move_deg = s.number("min_move_deg").value_or(h.min_move_deg);
  return h;
}

bool is_sha256_hex(const std::string& text) {
  return text.size() == 64 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

WebConfig read_web(const ConfigSection& s) {
  WebConfig w;
  w.bind = s.text("bind").value_or(w.bind);
  w.port = read_port(s, "port", w.port);
  w.password_hash = s.text("password_hash").value_or("");
  if (!w.password_hash.empty() && w.password_hash.rfind("$argon2id$", 0) != 0) {
    s.fail("password_hash", "must be an Argon2id hash as `azeltrack web password` writes it");
  }
  w.api_token_sha256 = s.text("api_token_sha256").value_or("");
  if (!w.api_token_sha256.empty() && !is_sha256_hex(w.api_token_sha256)) {
    s.fail("api_token_sha256", "must be 64 lower-case hex digits (`azeltrack web token`)");
  }
  if (const toml::array* hosts = s.array("allowed_hosts")) {
    for (const auto& h : *hosts) {
      const auto name = h.value<std::string>();
      if (!name || name->empty()) s.fail("allowed_hosts", "must hold host names");
      w.allowed_hosts.push_back(*name);
    }
  }
  return w;
}

/// [[token]]: each with a label of its own and a digest.
std::vector<WebToken> read_tokens(const ConfigFile& file) {
  std::vector<WebToken> out;
  for (const ConfigSection& s : file.section_array("token")) {
    WebToken t{s.text("label").value_or(""), s.text("sha256").value_or(""),
               s.text("created_utc").value_or("")};
    if (const auto why = token_label_problem(t.label)) s.fail("label", *why);
    if (!is_sha256_hex(t.sha256)) s.fail("sha256", "must be 64 lower-case hex digits");
    for (const auto& other : out) {
      if (other.label == t.label) s.fail("label", "\"" + t.label + "\" is used by two tokens");
    }
    out.push_back(std::move(t));
  }
  return out;
}

sequencer::SequencerConfig read_sequencer(const ConfigSection& s) {
  auto d = sequencer::SequencerConfig::seed_default();
  std::vector<std::string> outputs = d.outputs;
  if (const toml::array* a = s.array("outputs")) {
    outputs.clear();
    for (const auto& n : *a) {
      const auto name = n.value<std::string>();
      if (!name) s.fail("outputs", "must hold line names");
      outputs.push_back(*name);
    }
  }
  if (s.has("delay_ms") && s.has("delays_ms"))
    s.fail("delays_ms", "give delay_ms or delays_ms, not both");
  std::vector<double> delays(outputs.empty() ? 0 : outputs.size() - 1,
                             s.number("delay_ms").value_or(20.0));
  if (const toml::array* a = s.array("delays_ms")) {
    delays.clear();
    for (const auto& n : *a) {
      const auto v = n.value<double>();
      if (!v) s.fail("delays_ms", "must hold numbers");
      delays.push_back(*v);
    }
  }
  auto c = sequencer::SequencerConfig::make(
      outputs, delays, s.number("debounce_ms").value_or(d.debounce_ms),
      s.number("tx_timeout_s").value_or(d.tx_timeout_s), s.boolean("hold_motion").value_or(true));
  if (!c) {
    // "tx_timeout_s: 1 to 3600 …" -> the key, and the rule.
    const std::string& why = c.error().message;
    const auto colon = why.find(':');
    std::string key = why.substr(0, colon);
    if (key == "delays" || key == "delays_ms") key = s.has("delays_ms") ? "delays_ms" : "delay_ms";
    s.fail(key, "— " + (colon == std::string::npos ? why : why.substr(colon + 2)));
  }
  return *c;
}

linux_os::HubSerialConfig read_hub(const ConfigSection& s) {
  linux_os::HubSerialConfig h;
  h.device = s.text("device").value_or("");
  // 38400: what azeltrack's own hub firmware sends with no baud jumper (docs/encoder-hub.md).
  h.baud = static_cast<unsigned>(s.integer("baud").value_or(38400));
  h.accept = s.text("accept").value_or("crc8") == "seed" ? proto::HubAccept::SeedOnly
                                                         : proto::HubAccept::Crc8Only;
  return h;
}

/// The first of `seen` on the same chip and line as `line`, or null.
const linux_os::GpioLineSpec* same_line(const std::vector<const linux_os::GpioLineSpec*>& seen,
                                        const linux_os::GpioLineSpec& line) {
  for (const auto* other : seen) {
    if (other->chip == line.chip && other->offset == line.offset) return other;
  }
  return nullptr;
}

ButtonsConfig read_buttons(const ConfigSection& s, const std::string& chip) {
  ButtonsConfig b;
  // Push buttons to ground with the pull-ups: pressed reads low.
  const bool low = s.boolean("buttons_active_low").value_or(true);
  b.cw = read_gpio_line(s, "button_cw", chip, low);
  b.ccw = read_gpio_line(s, "button_ccw", chip, low);
  b.up = read_gpio_line(s, "button_up", chip, low);
  b.down = read_gpio_line(s, "button_down", chip, low);
  b.stop = read_gpio_line(s, "button_stop", chip, low);
  b.park = read_gpio_line(s, "button_park", chip, low);
  b.debounce_s = s.number("button_debounce_ms").value_or(b.debounce_s * 1000.0) / 1000.0;
  b.speed = s.number("button_speed").value_or(b.speed);
  b.park_slot = static_cast<int>(s.integer("button_park_slot").value_or(b.park_slot));
  return b;
}

GpioConfig read_gpio(const ConfigSection& s, std::size_t sequencer_outputs) {
  GpioConfig g;
  g.chip = s.text("chip").value_or(g.chip);
  // Normally closed switches to ground with pull-ups: an open switch or a cut wire reads high,
  // which is "tripped"; the radio's PTT output pulls its line low.
  const bool limits_low = s.boolean("limits_active_low").value_or(false);
  g.estop = read_gpio_line(s, "estop", g.chip, s.boolean("estop_active_low").value_or(false));
  g.az_ccw_limit = read_gpio_line(s, "az_ccw_limit", g.chip, limits_low);
  g.az_cw_limit = read_gpio_line(s, "az_cw_limit", g.chip, limits_low);
  g.el_down_limit = read_gpio_line(s, "el_down_limit", g.chip, limits_low);
  g.el_up_limit = read_gpio_line(s, "el_up_limit", g.chip, limits_low);
  g.pol_ccw_limit = read_gpio_line(s, "pol_ccw_limit", g.chip, limits_low);
  g.pol_cw_limit = read_gpio_line(s, "pol_cw_limit", g.chip, limits_low);
  g.ptt = read_gpio_line(s, "ptt", g.chip, s.boolean("ptt_active_low").value_or(true));
  const bool outputs_low = s.boolean("sequencer_active_low").value_or(false);
  if (const toml::array* a = s.array("sequencer")) {
    for (std::size_t i = 0; i < a->size(); ++i) {
      linux_os::GpioLineSpec spec{g.chip, 0, outputs_low,
                                  "[gpio] sequencer[" + std::to_string(i) + "]"};
      spec.offset = static_cast<unsigned>((*a)[i].value_or(std::int64_t{0}));  // 0 to 1023
      g.sequencer.push_back(spec);
    }
    if (g.sequencer.size() != sequencer_outputs) {
      s.fail("sequencer", "has " + std::to_string(g.sequencer.size()) + " lines for " +
                              std::to_string(sequencer_outputs) + " [sequencer] outputs");
    }
  }
  if (g.ptt && g.sequencer.empty()) s.fail("ptt", "needs the [gpio] sequencer output lines");
  g.buttons = read_buttons(s, g.chip);
  g.estop_latch_file = s.text("estop_latch_file").value_or("");
  // One line, one job: a line named twice would be requested twice (EBUSY) or, worse, wired to two
  // functions.
  std::vector<const linux_os::GpioLineSpec*> seen;
  for (const auto* l : g.lines()) {
    if (const auto* other = same_line(seen, *l)) {
      s.fail(l->key.substr(7), "is the same line as " + other->key);
    }
    seen.push_back(l);
  }
  return g;
}

PwmConfig read_pwm(const ConfigSection& s) {
  PwmConfig p;
  unsigned* channels[] = {&p.az.rpwm_channel, &p.az.lpwm_channel,  &p.el.rpwm_channel,
                          &p.el.lpwm_channel, &p.pol.rpwm_channel, &p.pol.lpwm_channel};
  const char* keys[] = {"az_rpwm", "az_lpwm", "el_rpwm", "el_lpwm", "pol_rpwm", "pol_lpwm"};
  for (std::size_t i = 0; i < 6; ++i) {
    *channels[i] = static_cast<unsigned>(s.integer(keys[i]).value_or(*channels[i]));
    for (std::size_t j = 0; j < i; ++j) {
      if (*channels[j] == *channels[i])
        s.fail(keys[i], std::string("is the same channel as ") + keys[j]);
    }
  }
  const double frequency_hz = s.number("frequency_hz").value_or(p.az.frequency_hz);
  const double dead_time_s = s.number("dead_time_s").value_or(p.az.dead_time_s);
  for (linux_os::PwmHBridgeConfig* bridge : {&p.az, &p.el, &p.pol}) {
    bridge->chip_dir = s.text("chip").value_or(bridge->chip_dir);
    bridge->frequency_hz = frequency_hz;
    bridge->dead_time_s = dead_time_s;
  }
  return p;
}

/// Four slots: the configured [[park]] entries in order, the rest from defaults inside the travel.
std::array<control::ParkSlot, control::ModeController::kParkSlots> read_park(
    const ConfigFile& file, const control::StationSetup& station) {
  const double el_low = station.el_range.min_deg;
  const double el_high = std::min(90.0, station.el_range.max_deg);
  const control::AzEl first = station.park_when_out_of_range.value_or(control::AzEl{180.0, el_low});
  std::array<control::ParkSlot, control::ModeController::kParkSlots> slots = {{
      {"park", first},
      {"stow", {180.0, el_high}},
      {"north", {0.0, el_low}},
      {"service", {90.0, el_low}},
  }};
  const auto entries = file.section_array("park");
  if (entries.size() > slots.size()) file.fail("at most 4 [[park]] slots");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const ConfigSection& s = entries[i];
    control::ParkSlot slot{
        s.text("name").value_or("park " + std::to_string(i + 1)),
        {s.number("az_deg").value_or(180.0), s.number("el_deg").value_or(el_low)}};
    if (!control::plan_elevation(slot.position.el_deg, station.el_range)) {
      s.fail("el_deg", "must be inside [geometry] el_min_deg..el_max_deg");
    }
    slots[i] = slot;
  }
  return slots;
}

/// A relay line that is also a [gpio] line (or another relay) would be driven by two functions.
void check_relay_lines(const DaemonConfig& c, const ConfigSection& antenna) {
  std::vector<const linux_os::GpioLineSpec*> seen = c.gpio.lines();
  for (const HardwareAxisConfig* a : c.hardware.axes()) {
    for (const auto* l : a->gpio_lines()) {
      if (const auto* other = same_line(seen, *l)) {
        antenna.fail("backend", l->key + " is the same line as " + other->key);
      }
      seen.push_back(l);
    }
  }
}

/// [hardware.power] works with any backend; its line must be free, and "sim" only simulated.
void check_power_relay(const DaemonConfig& c, const ConfigSection& antenna) {
  const auto& power = c.hardware.power;
  if (!power) return;
  if (power->simulated() && c.backend != BackendKind::Sim) {
    antenna.fail("backend", "[hardware.power] relay on \"sim\" needs backend = \"sim\"");
  }
  std::vector<const linux_os::GpioLineSpec*> seen = c.gpio.lines();
  for (const HardwareAxisConfig* a : c.hardware.axes()) {
    if (c.backend != BackendKind::Hardware) break;
    for (const auto* l : a->gpio_lines()) seen.push_back(l);
  }
  if (const auto* other = same_line(seen, power->relay)) {
    antenna.fail("backend", power->relay.key + " is the same line as " + other->key);
  }
}

}  // namespace

control::AzEl DaemonConfig::start_mount() const {
  if (backend == BackendKind::Sim) return control::AzEl{sim.az.start_deg, sim.el.start_deg};
  return station.believed_start();
}

proto::TargetLimits DaemonConfig::target_limits() const {
  proto::TargetLimits l;
  l.az_min_deg = std::min(-180.0, station.az_range.min_deg);
  l.az_max_deg = std::max(450.0, station.az_range.max_deg);
  l.el_min_deg = station.el_range.min_deg;
  l.el_max_deg = station.el_range.max_deg;
  return l;
}

namespace {

/// [target] name: what to track at start.
void read_start_target(const ConfigFile& file, DaemonConfig& c) {
  const ConfigSection target = file.section("target");
  c.start_target = target.text("name").value_or("moon");
  // "sat:NAME" is looked up in the satellite catalogue when the daemon starts.
  if (c.start_target != "stop" &&
      std::holds_alternative<NamedTarget>(target_from_name(c.start_target)) &&
      !find_sky_target(c.sky, c.start_target)) {
    target.fail("name", "'" + c.start_target +
                            "' is not a target of this station: sun, moon, a [sky] source, "
                            "sat:NAME, or \"stop\"");
  }
}

/// [antenna] backend and what it needs: [hub], [pwm], [hamlib], [hardware.*] (after [gpio]).
void read_antenna(const ConfigFile& file, DaemonConfig& c) {
  const ConfigSection antenna = file.section("antenna");
  c.backend = antenna.choice("backend", kBackendKinds, BackendKind::Sim);
  c.hub = read_hub(file.section("hub"));
  c.pwm = read_pwm(file.section("pwm"));
  if (c.backend == BackendKind::Pwm && c.hub.device.empty()) {
    antenna.fail("backend", "is \"pwm\" but [hub] device is not set");
  }
  const ConfigSection hamlib = file.section("hamlib");
  c.hamlib = read_hamlib(hamlib);
  if (c.backend == BackendKind::Hamlib && !hamlib.present()) {
    antenna.fail("backend", "is \"hamlib\" but there is no [hamlib] table");
  }
  c.hardware = read_hardware(file, c.gpio.chip, !c.mount.el_fixed);
  if (c.backend == BackendKind::Hardware) {
    if (c.hardware.uses_hub() && c.hub.device.empty()) {
      antenna.fail("backend", "is \"hardware\" with a hub sensor but [hub] device is not set");
    }
    check_relay_lines(c, antenna);
  }
  check_power_relay(c, antenna);
}

/// The PC programs' servers: [rotctld], [pstrotator], [[serial]].
void read_servers(const ConfigFile& file, DaemonConfig& c) {
  const ConfigSection rotctld = file.section("rotctld");
  c.rotctld = read_net(rotctld, c.rotctld);
  if (const auto idle = rotctld.number("idle_timeout_s")) {
    // 0 turns it off; below 10 s a client polling every few seconds would be cut.
    if (*idle != 0.0 && *idle < 10.0) {
      rotctld.fail("idle_timeout_s", "must be 0 (never) or 10 to 86400 seconds");
    }
    c.rotctld_idle_timeout_s = *idle;
  }
  const ConfigSection pst = file.section("pstrotator");
  c.pstrotator = read_net(pst, c.pstrotator);
  c.pstrotator_reply_port =
      read_port(pst, "reply_port", c.pstrotator.port == 0 ? 0 : c.pstrotator.port + 1);
  c.serial = read_serial(file);
}

}  // namespace

namespace {

/// [satellites]: the catalogue, its horizon and the pass planner's beamwidth, the network
/// sources and how they are fetched, and the element-age limits.
SatellitesConfig read_satellites(const ConfigSection& sats) {
  SatellitesConfig c;
  c.file = sats.text("file").value_or("");
  c.mask = sats.text("mask").value_or("0");
  try {
    (void)parse_horizon_mask("mask", c.mask);
  } catch (const UsageError& e) {
    sats.fail("mask", std::string(e.what()).substr(6));
  }
  c.beamwidth_deg = sats.number("beamwidth_deg").value_or(c.beamwidth_deg);
  if (const toml::array* urls = sats.array("sources")) {
    for (const auto& item : *urls) {
      const auto url = item.value<std::string>();
      if (!url || url->empty()) sats.fail("sources", "must hold URLs");
      c.sources.push_back(*url);
    }
  }
  c.refresh_h = sats.number("refresh_h").value_or(c.refresh_h);
  c.stale_days = sats.number("stale_days").value_or(c.stale_days);
  c.refuse_days = sats.number("refuse_days").value_or(c.refuse_days);
  if (c.refuse_days < c.stale_days) sats.fail("refuse_days", "must not be below stale_days");
  c.idle_park_min = sats.number("idle_park_min").value_or(c.idle_park_min);
  c.min_el_deg = sats.number("min_el_deg").value_or(c.min_el_deg);
  c.ca_file = sats.text("ca_file").value_or("");
  c.proxy = sats.text("proxy").value_or("");
  c.connect_timeout_s = sats.number("connect_timeout_s").value_or(c.connect_timeout_s);
  c.timeout_s = sats.number("timeout_s").value_or(c.timeout_s);
  c.max_mb = sats.number("max_mb").value_or(c.max_mb);
  c.max_redirects = static_cast<long>(sats.integer("max_redirects").value_or(c.max_redirects));
  return c;
}

}  // namespace

DaemonConfig daemon_config_from(const ConfigFile& file) {
  DaemonConfig c;
  const SimConfig sim = sim_config_from(file);
  c.sky = sim.sky;
  c.mount = sim.mount;
  c.station = sim.setup.station;
  c.sim = sim.setup.plant;
  c.sim_motors = sim.setup.motors;
  c.sim_hub = sim.hub;
  c.sim_receiver = sim.receiver;
  c.pol = sim.pol;
  read_start_target(file, c);
  c.sequencer = read_sequencer(file.section("sequencer"));
  c.gpio = read_gpio(file.section("gpio"), c.sequencer.outputs.size());
  c.gamepad = read_gamepad(file);
  read_antenna(file, c);
  check_pol_backend(file, c);
  read_servers(file, c);
  const ConfigSection sats = file.section("satellites");
  c.gps = gps_config_from(file);
  c.radio = radio_config_from(file);
  c.wsjtx = wsjtx_config_from(file);
  c.receiver = receiver_config_from(file);
  if (c.receiver.source == ReceiverConfig::Source::Sim && c.backend != BackendKind::Sim) {
    file.section("receiver")
        .fail("source", "\"sim\" hears the simulated antenna: [antenna] backend must be \"sim\"");
  }
  c.time = time_config_from(file);
  c.exports = export_config_from(file);
  c.satellites = read_satellites(sats);
  c.schedule = schedule_config_from(file);
  c.hooks = hooks_config_from(file);
  c.web = read_web(file.section("web"));
  c.web.tokens = read_tokens(file);
  c.park = read_park(file, c.station);
  if (c.station.park_when_out_of_range) c.out_of_range = control::OutOfRangePolicy::Park;
  c.log_level = file.section("log").text("level").value_or("info");
  return c;
}

std::vector<const linux_os::GpioLineSpec*> GpioConfig::lines() const {
  std::vector<const linux_os::GpioLineSpec*> out;
  for (const auto* l : {&estop, &az_ccw_limit, &az_cw_limit, &el_down_limit, &el_up_limit,
                        &pol_ccw_limit, &pol_cw_limit, &ptt}) {
    if (*l) out.push_back(&**l);
  }
  for (const auto* l : buttons.lines()) out.push_back(l);
  for (const auto& l : sequencer) out.push_back(&l);
  return out;
}

std::vector<const linux_os::GpioLineSpec*> ButtonsConfig::lines() const {
  std::vector<const linux_os::GpioLineSpec*> out;
  for (const auto* l : {&cw, &ccw, &up, &down, &stop, &park}) {
    if (*l) out.push_back(&**l);
  }
  return out;
}

DaemonConfig load_daemon_config(const std::string& path) {
  return daemon_config_from(ConfigFile::load(path));
}

}  // namespace azt::app
