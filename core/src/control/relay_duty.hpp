#pragma once
// A relay command as the duty DrivenAxis reports and drives (+1, −1, 0): shared by its tracking
// drive (driven_axis.cpp) and its homing moves (driven_axis_pulses.cpp). Internal to the core.

#include "azt/control/relay_drive.hpp"

namespace azt::control {

inline double relay_duty(RelayCommand command) {
  switch (command) {
    case RelayCommand::Forward:
      return 1.0;
    case RelayCommand::Reverse:
      return -1.0;
    case RelayCommand::Off:
      break;
  }
  return 0.0;
}

}  // namespace azt::control
