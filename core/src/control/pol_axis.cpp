#include "azt/control/pol_axis.hpp"

#include <cmath>

#include "azt/control/pulse_axis.hpp"

namespace azt::control {

PolAxis::PolAxis(const PolAxisConfig& config, double tick_s)
    : axis_(config.control, config.supervisor, config.drive, config.start_mount_deg, tick_s),
      travel_(config.travel) {}

void PolAxis::on_reading(double now_s, double sensor_deg) {
  // A pol travel is narrower than a turn, so the nearest equivalent is the only one near it.
  const double present = axis_.mount_deg();
  axis_.on_reading(now_s, present + std::remainder(sensor_deg - present, 360.0));
}

double PolAxis::drive(double now_s, const PolDemand& demand) {
  target_mount_deg_.reset();
  if (demand.test_direction != 0)
    return axis_.drive_test(now_s, demand.test_direction > 0 ? 1 : -1);
  if (demand.feed_deg && std::isfinite(*demand.feed_deg)) {
    target_mount_deg_ = plan_pol_mount(axis_.mount_deg(), *demand.feed_deg, travel_);
  }
  const double rate =
      target_mount_deg_ && std::isfinite(demand.rate_deg_s) ? demand.rate_deg_s : 0.0;
  const double duty = axis_.drive(now_s, target_mount_deg_, rate);
  // A pulse-counted feed not homed held instead (DrivenAxis::drive): it was sent nowhere.
  if (const PulseAxis* p = axis_.pulses(); p != nullptr && !p->homed()) target_mount_deg_.reset();
  return duty;
}

}  // namespace azt::control
