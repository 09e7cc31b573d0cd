#pragma once
// What the daemon's polarisation axis follows, tick by tick (docs/eme.md, "Polarisation axis"):
// the [pol] mode and angles (changed at run time by the console), Dpol to the DX station, the
// transmitter's key and the operator's manual angle, turned into the axis's demand by the core's
// pol_feed_deg.
//
// Dpol turns slowly (hundredths of a degree a second away from the zenith) but costs two Moon
// positions: it is computed at whole multiples of kDpolNodeS of UTC, one node ahead, and
// interpolated between, so a tick computes at most one node and most compute none (the tick's
// lateness budget, docs/daemon.md). The interpolation's slope is the feed-forward rate of the
// modes that follow Dpol.

#include <functional>
#include <optional>

#include "azt/control/pol_axis.hpp"
#include "azt/control/pol_target.hpp"

namespace azt::app {

struct PolFollowerParts {
  control::PolSettings settings;  ///< [pol] as the daemon starts
  /// Dpol at a UTC instant (unix seconds); nullopt without a DX station (moon_dpol.hpp).
  std::function<std::optional<double>(double unix_s)> dpol_deg;
  /// The transmitter keyed: the sequencer's PTT, or WSJT-X transmitting.
  std::function<bool()> transmitting;
};

class PolFollower {
 public:
  static constexpr double kDpolNodeS = 10.0;

  explicit PolFollower(PolFollowerParts parts);

  /// One tick at `unix_s`: the axis's demand (nullopt feed: it holds where it stands).
  control::PolDemand demand(double unix_s);

  /// A mode or angle chosen at run time (the console's POST /api/pol, once saved).
  void set_settings(const control::PolSettings& settings) { parts_.settings = settings; }
  /// The operator's angle for Manual (feed degrees); nullopt: none given yet (Manual holds).
  void set_manual_deg(std::optional<double> deg) { manual_deg_ = deg; }
  /// The DX station changed (the console, WSJT-X): Dpol is computed afresh at the next tick.
  void forget_dpol() { nodes_.reset(); }

  [[nodiscard]] const control::PolSettings& settings() const { return parts_.settings; }
  [[nodiscard]] std::optional<double> manual_deg() const { return manual_deg_; }
  /// As at the last tick: Dpol, whether keyed, and the feed angle asked for.
  [[nodiscard]] std::optional<double> dpol_deg() const { return last_.spatial_offset_deg; }
  [[nodiscard]] bool transmitting() const { return last_.transmitting; }
  [[nodiscard]] std::optional<double> feed_deg() const { return last_feed_deg_; }

 private:
  /// Dpol at two successive nodes: `index` and `index + 1`.
  struct Nodes {
    double index = 0.0;
    std::optional<double> at_index;
    std::optional<double> at_next;
  };
  /// Dpol at `unix_s` interpolated between its nodes, and its rate (deg/s).
  std::optional<double> dpol_at(double unix_s, double& rate_deg_s);
  [[nodiscard]] bool follows_dpol() const;

  PolFollowerParts parts_;
  std::optional<double> manual_deg_;
  std::optional<Nodes> nodes_;
  control::PolInputs last_;
  std::optional<double> last_feed_deg_;
};

}  // namespace azt::app
