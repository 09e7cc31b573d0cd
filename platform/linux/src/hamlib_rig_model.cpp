#include "azt/linux/hamlib_rig_model.hpp"

#include <mutex>

// Hamlib's C headers are not clean under -Wpedantic/-Wconversion; keep them out of our warnings.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <hamlib/rig.h>
#pragma GCC diagnostic pop

#include "hamlib_process.hpp"

namespace azt::linux_os {
namespace {

HamlibPortKind port_kind(rig_port_t port) {
  switch (port) {
    case RIG_PORT_NONE:
      return HamlibPortKind::None;
    case RIG_PORT_SERIAL:
      return HamlibPortKind::Serial;
    case RIG_PORT_NETWORK:
    case RIG_PORT_UDP_NETWORK:
      return HamlibPortKind::Network;
    default:
      return HamlibPortKind::Other;  // USB, parallel, GPIO, …: Hamlib's own ways
  }
}

std::string text_or_unknown(const char* text) { return text != nullptr ? text : "?"; }

}  // namespace

std::string describe_hamlib_rig(const HamlibRigConfig& config) {
  return "Hamlib rig model " + std::to_string(config.model) +
         (config.device.empty() ? std::string() : " on " + config.device);
}

Result<HamlibRigModel> hamlib_rig_model(int model) {
  quiet_hamlib();
  const std::lock_guard lock(hamlib_global_mutex());
  // rig_get_caps only sees backends already registered. Every backend is registered once, here
  // (they are built into the library: nothing is read). Not rig_check_backend per model: in
  // Hamlib 4.5 it registers a loaded backend again when the model number is not one of its rigs,
  // and the duplicate makes rig_register print "Hash collision!!! Fatal error!!" and exit(1), so
  // a second file naming model 1070 would end the daemon (found by config_fuzz).
  static std::once_flag registered;
  std::call_once(registered, [] { rig_load_all_backends(); });
  const rig_caps* caps = model > 0 ? rig_get_caps(static_cast<rig_model_t>(model)) : nullptr;
  if (caps == nullptr) {
    return fail("Hamlib has no rig model " + std::to_string(model) + " (`rigctl -l` lists them)");
  }
  HamlibRigModel m;
  m.name = text_or_unknown(caps->mfg_name) + " " + text_or_unknown(caps->model_name);
  m.port = port_kind(caps->port_type);
  return m;
}

std::string hamlib_rig_config_problem(const HamlibRigConfig& config) {
  const auto model = hamlib_rig_model(config.model);
  if (!model) return model.error().message;
  if (config.baud == 0) return "";
  const std::string named = "model " + std::to_string(config.model) + " (" + model->name + ")";
  if (model->port != HamlibPortKind::Serial) return named + " is not a serial rig: baud must be 0";
  return "";
}

}  // namespace azt::linux_os
