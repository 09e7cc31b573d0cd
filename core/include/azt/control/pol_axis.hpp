#pragma once
// The polarisation axis (docs/eme.md, "Polarisation axis"): a third driven axis that turns a
// linear feed, or a whole array, to the feed angle pol_target.hpp chooses. It is a DrivenAxis
// like azimuth and elevation (the same drives, the same supervisor: stale, stall, runaway,
// limits) whose target is placed inside its own travel, at the equivalent angle nearest where it
// stands.

#include <optional>

#include "azt/control/driven_axis.hpp"
#include "azt/control/pol_target.hpp"

namespace azt::control {

struct PolAxisConfig {
  AxisControlConfig control;  ///< lsb_deg is the pol sensor's step
  SupervisorConfig supervisor;
  AxisDriveConfig drive;
  PolTravel travel;
  /// Where the feed is believed to be before the first reading (it only decides which turn a
  /// single-turn sensor's first reading is taken on).
  double start_mount_deg = 0.0;
};

/// One tick's wish for the pol axis: the feed angle (pol_feed_deg; nullopt holds the axis where
/// it stands) and how fast it moves (deg/s, feed-forward while following the Moon).
struct PolDemand {
  std::optional<double> feed_deg;
  double rate_deg_s = 0.0;
  /// The console's direction test: +1 or −1 drives the axis slowly that way, open loop
  /// (DrivenAxis::drive_test), whatever feed_deg says; 0 is the normal demand.
  int test_direction = 0;
};

class PolAxis {
 public:
  PolAxis(const PolAxisConfig& config, double tick_s);

  /// A sensor reading in degrees (0..360 from a single-turn encoder, or a mount angle): placed at
  /// the equivalent angle nearest the present one, so the reading keeps its side of the travel.
  void on_reading(double now_s, double sensor_deg);
  /// One tick: the mount target for `demand` inside the travel, driven. Returns the duty.
  double drive(double now_s, const PolDemand& demand);

  /// The mount angle the axis was last sent to; nullopt while it holds.
  [[nodiscard]] std::optional<double> target_mount_deg() const { return target_mount_deg_; }
  [[nodiscard]] DrivenAxis& axis() { return axis_; }
  [[nodiscard]] const DrivenAxis& axis() const { return axis_; }
  [[nodiscard]] const PolTravel& travel() const { return travel_; }

 private:
  DrivenAxis axis_;
  PolTravel travel_;
  std::optional<double> target_mount_deg_;
};

}  // namespace azt::control
