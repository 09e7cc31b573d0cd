#include "azt/control/station_setup.hpp"

#include <algorithm>

namespace azt::control {

StationControlConfig StationSetup::control_config() const {
  StationControlConfig c;
  c.az_control = az_control;
  c.el_control = el_control;
  c.az_supervisor = az_supervisor;
  c.el_supervisor = el_supervisor;
  c.az_range = az_range;
  c.el_range = el_range;
  c.tick_s = tick_s;
  c.pol = pol;
  c.el_fixed_deg = el_fixed_deg;
  return c;
}

AzEl StationSetup::believed_start() const {
  return AzEl{std::clamp(0.0, az_range.min_deg, az_range.max_deg),
              el_fixed_deg.value_or(std::clamp(0.0, el_range.min_deg, el_range.max_deg))};
}

}  // namespace azt::control
