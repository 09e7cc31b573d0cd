// The polarisation axis in the daemon (docs/eme.md, "Polarisation axis"): the follower that
// turns [pol], Dpol to the DX station and the transmitter's key into the axis's demand each tick.
#include <spdlog/spdlog.h>

#include "common/moon_dpol.hpp"
#include "daemon/station_daemon.hpp"

namespace azt::app {

std::unique_ptr<PolFollower> StationDaemon::make_pol_follower() {
  // The backend says whether there is an axis: [mount.pol] with its plant or its devices.
  if (!antenna_->pol_status()) return nullptr;
  spdlog::info("polarisation axis: mode {}", control::to_string(config_.pol.mode));
  return std::make_unique<PolFollower>(PolFollowerParts{
      config_.pol,
      [this](double unix_s) { return moon_dpol_deg(*ephemeris_, config_.sky.settings, unix_s); },
      [this] { return sequencer_->transmitting() || (radio_ && radio_->wsjtx_transmitting()); }});
}

void StationDaemon::pol_tick() {
  if (!pol_) return;
  // Another DX station (the console, or WSJT-X's DX grid): its Dpol, not the last one's nodes.
  if (config_.sky.settings.dx_grid != pol_dx_grid_) {
    pol_dx_grid_ = config_.sky.settings.dx_grid;
    pol_->forget_dpol();
  }
  const control::PolDemand demand = pol_->demand(unix_now_s());
  // The motors' supply off ([hardware.power], the schedule's idle power-off): the pol motor has
  // none either, so it holds rather than stall against nothing.
  const bool unpowered = power_ && power_->motion_hold(now_s());
  antenna_->set_pol_demand(unpowered ? control::PolDemand{} : demand);
}

}  // namespace azt::app
