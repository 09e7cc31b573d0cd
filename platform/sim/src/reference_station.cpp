#include "azt/sim/reference_station.hpp"
#include "azt/proto/hub_frame.hpp"

#include <cmath>
#include <utility>

namespace azt::sim {

StationSimSetup reference_station(int bits, double window_deg) {
  StationSimSetup s;
  s.az_plant.max_rate_deg_s = 1.5;
  s.el_plant.max_rate_deg_s = 1.0;
  s.az_plant.start_deg = 180.0;
  s.el_plant.start_deg = 10.0;
  s.az_plant.min_deg = 0.0;
  s.az_plant.max_deg = 360.0;
  s.el_plant.min_deg = 0.0;
  s.el_plant.max_deg = 90.0;
  for (AxisParams* p : {&s.az_plant, &s.el_plant}) {
    p->time_constant_s = 0.3;
    p->backlash_deg = 0.05;
    p->stiction_duty = 0.1;
    p->encoder_bits = static_cast<std::uint8_t>(bits);
  }
  for (auto [c, p] : {std::pair{&s.station.az_control, &s.az_plant},
                      std::pair{&s.station.el_control, &s.el_plant}}) {
    c->window_deg = window_deg;
    c->lsb_deg = proto::hub_resolution_deg(p->encoder_bits);
    c->max_rate_deg_s = p->max_rate_deg_s;
    c->time_constant_s = p->time_constant_s;
    c->min_duty = p->stiction_duty;
    c->backlash_deg = p->backlash_deg;
  }
  s.station.az_supervisor.max_rate_deg_s = s.az_plant.max_rate_deg_s;
  s.station.el_supervisor.max_rate_deg_s = s.el_plant.max_rate_deg_s;
  s.station.az_supervisor.lsb_deg = s.station.az_control.lsb_deg;
  s.station.el_supervisor.lsb_deg = s.station.el_control.lsb_deg;
  return s;
}

}  // namespace azt::sim
