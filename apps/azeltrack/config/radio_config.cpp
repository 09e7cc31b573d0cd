#include "config/radio_config.hpp"

#include "config/config_choice.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

constexpr ConfigChoices<DopplerSource, 3> kDoppler{{{"off", DopplerSource::Off},
                                                    {"satellite", DopplerSource::Satellite},
                                                    {"eme", DopplerSource::Eme}}};
constexpr ConfigChoices<radio::TransponderMode, 3> kModes{
    {{"fm", radio::TransponderMode::Fm},
     {"linear", radio::TransponderMode::Linear},
     {"linear_inverting", radio::TransponderMode::LinearInverting}}};

std::optional<HostPort> endpoint(const ConfigSection& s, std::string_view key) {
  const auto text = s.text(key).value_or("");
  if (text.empty()) return std::nullopt;
  return parse_host_port(s, key, text, "127.0.0.1:4532");
}

/// `model`, `device`, `baud` (with `prefix`: `tx_model`, …): a rig through libhamlib, checked
/// against Hamlib's own list of models now rather than when the daemon first opens it.
std::optional<linux_os::HamlibRigConfig> direct_rig(const ConfigSection& s,
                                                    const std::string& prefix, bool rigctld_too) {
  const std::string model_key = prefix + "model";
  linux_os::HamlibRigConfig c;
  c.model = static_cast<int>(s.integer(model_key).value_or(0));  // 0 to 100000 (the schema)
  c.device = s.text(prefix + "device").value_or("");
  c.baud = static_cast<int>(s.integer(prefix + "baud").value_or(0));
  if (c.model == 0) {
    if (!c.device.empty())
      s.fail(prefix + "device", "needs " + model_key + " (the rig's Hamlib model)");
    if (c.baud != 0) s.fail(prefix + "baud", "needs " + model_key + " (the rig's Hamlib model)");
    return std::nullopt;
  }
  if (rigctld_too) {
    s.fail(model_key, "and " + prefix + "rigctld both name the rig: set one of them");
  }
  if (const auto problem = linux_os::hamlib_rig_config_problem(c); !problem.empty()) {
    s.fail(model_key, problem);
  }
  return c;
}

std::vector<TransmitterConfig> read_transmitters(const ConfigFile& file) {
  std::vector<TransmitterConfig> out;
  for (const ConfigSection& t : file.section("satellites").child_array("transmitter")) {
    TransmitterConfig c;
    const auto norad = t.text("norad");
    if (!norad || norad->empty()) t.fail("norad", "is required (the satellite's NORAD number)");
    c.norad = *norad;
    const auto down = t.number("downlink_mhz");
    if (!down || *down <= 0.0) t.fail("downlink_mhz", "is required and above 0");
    c.transmitter.downlink_hz = *down * 1e6;
    if (const auto up = t.number("uplink_mhz"); up && *up > 0.0) {
      c.transmitter.uplink_hz = *up * 1e6;
    }
    c.transmitter.mode = t.choice("mode", kModes, radio::TransponderMode::Fm);
    if (c.transmitter.mode != radio::TransponderMode::Fm && !c.transmitter.uplink_hz) {
      t.fail("uplink_mhz", "a linear transponder needs its uplink (the passband's pair)");
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

const TransmitterConfig* RadioConfig::transmitter_of(const std::string& norad) const {
  for (const auto& t : transmitters) {
    if (t.norad == norad) return &t;
  }
  return nullptr;
}

std::string_view doppler_source_name(DopplerSource source) { return name_of(kDoppler, source); }

std::string_view transponder_mode_name(radio::TransponderMode mode) {
  return name_of(kModes, mode);
}

RadioConfig radio_config_from(const ConfigFile& file) {
  const ConfigSection s = file.section("radio");
  RadioConfig c;
  c.rigctld = endpoint(s, "rigctld");
  c.hamlib = direct_rig(s, "", c.rigctld.has_value());
  c.tx_rigctld = endpoint(s, "tx_rigctld");
  c.tx_hamlib = direct_rig(s, "tx_", c.tx_rigctld.has_value());
  if (c.hamlib && c.tx_hamlib && !c.hamlib->device.empty() &&
      c.hamlib->device == c.tx_hamlib->device) {
    s.fail("tx_device", "is `device` too: two rigs cannot share one port");
  }
  if ((c.tx_rigctld || c.tx_hamlib) && !c.has_rig()) {
    s.fail(c.tx_rigctld ? "tx_rigctld" : "tx_model",
           "names the uplink's rig, but there is no rig: rigctld = \"HOST:PORT\" or model = N");
  }
  c.doppler = s.choice("doppler", kDoppler, DopplerSource::Off);
  if (const auto mode = s.text("eme_mode")) c.eme_mode = *radio::parse_eme_mode(*mode);
  c.dial_mhz = s.number("dial_mhz").value_or(0.0);
  c.step_hz = s.number("step_hz").value_or(10.0);
  c.no_tx_qsy = s.boolean("no_tx_qsy").value_or(false);
  c.transmitters = read_transmitters(file);
  if (c.doppler != DopplerSource::Off && !c.has_rig()) {
    s.fail("rigctld", "a Doppler source needs the rig: rigctld = \"HOST:PORT\" or model = N");
  }
  if (c.doppler == DopplerSource::Eme && c.dial_mhz <= 0.0) {
    s.fail("dial_mhz", "EME Doppler needs the nominal dial frequency");
  }
  return c;
}

}  // namespace azt::app
