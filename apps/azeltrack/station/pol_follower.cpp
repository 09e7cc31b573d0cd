#include "station/pol_follower.hpp"

#include <cmath>
#include <utility>

namespace azt::app {

PolFollower::PolFollower(PolFollowerParts parts) : parts_(std::move(parts)) {}

std::optional<double> PolFollower::dpol_at(double unix_s, double& rate_deg_s) {
  rate_deg_s = 0.0;
  if (!parts_.dpol_deg) return std::nullopt;
  const double index = std::floor(unix_s / kDpolNodeS);
  if (!nodes_ || nodes_->index != index) {
    // Walking forward by one node reuses the one ahead: one Moon computation per node.
    const bool next = nodes_ && nodes_->index + 1.0 == index;
    Nodes fresh{index, next ? nodes_->at_next : parts_.dpol_deg(index * kDpolNodeS),
                parts_.dpol_deg((index + 1.0) * kDpolNodeS)};
    nodes_ = fresh;
  }
  if (!nodes_->at_index || !nodes_->at_next) return nodes_->at_index;
  // Across the fold at ±90° the shorter way round (a linear polarisation repeats every 180°).
  const double step = std::remainder(*nodes_->at_next - *nodes_->at_index, 180.0);
  rate_deg_s = step / kDpolNodeS;
  const double fraction = unix_s / kDpolNodeS - index;
  return control::fold_linear_deg(*nodes_->at_index + fraction * step);
}

bool PolFollower::follows_dpol() const {
  switch (parts_.settings.mode) {
    case control::PolMode::Dx:
    case control::PolMode::Split:
      return true;
    case control::PolMode::Off:
    case control::PolMode::Fixed:
    case control::PolMode::Manual:
    case control::PolMode::Self:
      return false;
  }
  return false;
}

control::PolDemand PolFollower::demand(double unix_s) {
  double rate_deg_s = 0.0;
  last_.spatial_offset_deg = dpol_at(unix_s, rate_deg_s);
  last_.transmitting = parts_.transmitting && parts_.transmitting();
  last_.manual_deg = manual_deg_;
  last_feed_deg_ = control::pol_feed_deg(parts_.settings, last_);
  if (!last_feed_deg_ || !follows_dpol()) rate_deg_s = 0.0;
  return control::PolDemand{last_feed_deg_, rate_deg_s};
}

}  // namespace azt::app
