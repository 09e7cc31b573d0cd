#include "azt/control/station_setup.hpp"

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
  return c;
}

}  // namespace azt::control
