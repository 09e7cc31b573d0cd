#pragma once
// How the station reaches its rigs (docs/radio.md "Through rigctld or directly"): each of the
// main rig ([radio] rigctld or model) and the uplink's rig ([radio] tx_rigctld or tx_model) is
// either Hamlib's rigctld over TCP (platform/linux rigctld_link) or libhamlib directly on a
// worker thread (hamlib_rig). The Doppler cycle sees either through the core's RigPort.

#include <functional>
#include <memory>
#include <string>

#include "azt/linux/asio.hpp"
#include "azt/linux/rig_connection.hpp"
#include "config/radio_config.hpp"
#include "radio/rig_doppler_cycle.hpp"

namespace azt::app {

/// The link to the rig that carries `role`, connecting at once; null when the configuration names
/// none. `now_s`: a monotonic clock (rigctld's reply timeout).
std::unique_ptr<linux_os::RigConnection> open_rig_link(boost::asio::io_context& io,
                                                       const RadioConfig& config, RigRole role,
                                                       std::function<double()> now_s,
                                                       linux_os::RigLinkEvents events);

/// The rig's name in the log: "radio: rigctld at 127.0.0.1:4532", "radio: uplink Hamlib rig
/// model 1020 on /dev/ttyUSB1".
std::string rig_link_name(const RadioConfig& config, RigRole role);

}  // namespace azt::app
