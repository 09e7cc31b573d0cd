#include "azt/sim/reference_station.hpp"
#include "azt/proto/hub_frame.hpp"

#include <cmath>
#include <utility>

namespace azt::sim {

StationSimSetup reference_station(int bits, double window_deg) {
  StationSimSetup s;
  s.plant.az.max_rate_deg_s = 1.5;
  s.plant.el.max_rate_deg_s = 1.0;
  s.plant.az.start_deg = 180.0;
  s.plant.el.start_deg = 10.0;
  s.plant.az.min_deg = 0.0;
  s.plant.az.max_deg = 360.0;
  s.plant.el.min_deg = 0.0;
  s.plant.el.max_deg = 90.0;
  for (AxisParams* p : {&s.plant.az, &s.plant.el}) {
    p->time_constant_s = 0.3;
    p->backlash_deg = 0.05;
    p->stiction_duty = 0.1;
    p->encoder_bits = static_cast<std::uint8_t>(bits);
  }
  for (auto [c, p] : {std::pair{&s.station.az_control, &s.plant.az},
                      std::pair{&s.station.el_control, &s.plant.el}}) {
    c->window_deg = window_deg;
    c->lsb_deg = proto::hub_resolution_deg(p->encoder_bits);
    c->max_rate_deg_s = p->max_rate_deg_s;
    c->time_constant_s = p->time_constant_s;
    c->min_duty = p->stiction_duty;
    c->backlash_deg = p->backlash_deg;
  }
  s.station.az_supervisor.max_rate_deg_s = s.plant.az.max_rate_deg_s;
  s.station.el_supervisor.max_rate_deg_s = s.plant.el.max_rate_deg_s;
  s.station.az_supervisor.lsb_deg = s.station.az_control.lsb_deg;
  s.station.el_supervisor.lsb_deg = s.station.el_control.lsb_deg;
  return s;
}

}  // namespace azt::sim
