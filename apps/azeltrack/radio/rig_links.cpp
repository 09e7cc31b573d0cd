#include "radio/rig_links.hpp"

#include <optional>
#include <utility>

#include "azt/linux/hamlib_rig.hpp"
#include "azt/linux/rigctld_link.hpp"

namespace azt::app {
namespace {

const std::optional<HostPort>& rigctld_of(const RadioConfig& config, RigRole role) {
  switch (role) {
    case RigRole::Main:
      return config.rigctld;
    case RigRole::Uplink:
      return config.tx_rigctld;
  }
  return config.rigctld;
}

const std::optional<linux_os::HamlibRigConfig>& hamlib_of(const RadioConfig& config, RigRole role) {
  switch (role) {
    case RigRole::Main:
      return config.hamlib;
    case RigRole::Uplink:
      return config.tx_hamlib;
  }
  return config.hamlib;
}

}  // namespace

std::unique_ptr<linux_os::RigConnection> open_rig_link(boost::asio::io_context& io,
                                                       const RadioConfig& config, RigRole role,
                                                       std::function<double()> now_s,
                                                       linux_os::RigLinkEvents events) {
  if (const auto& where = rigctld_of(config, role)) {
    linux_os::RigctldLinkConfig c;
    c.host = where->host;
    c.port = std::to_string(where->port);
    return std::make_unique<linux_os::RigctldLink>(io, c, std::move(now_s), std::move(events));
  }
  if (const auto& rig = hamlib_of(config, role)) {
    return std::make_unique<linux_os::HamlibRig>(io, *rig, linux_os::HamlibRigOptions(),
                                                 std::move(events));
  }
  return nullptr;
}

std::string rig_link_name(const RadioConfig& config, RigRole role) {
  const std::string prefix = role == RigRole::Main ? "radio: " : "radio: uplink ";
  if (const auto& where = rigctld_of(config, role)) return prefix + "rigctld at " + where->text();
  if (const auto& rig = hamlib_of(config, role))
    return prefix + linux_os::describe_hamlib_rig(*rig);
  return prefix + "no rig";
}

}  // namespace azt::app
