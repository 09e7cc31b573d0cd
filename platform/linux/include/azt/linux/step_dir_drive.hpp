#pragma once
// A stepper on a step/direction driver (docs/hardware.md, "Steppers"): STEP on a sysfs PWM
// channel, whose frequency is the step rate (a hardware pulse train: no pulse depends on the
// loop's timing), DIR and the driver's ENABLE on GPIO lines. The core's StepDir decides the rate
// the motor can follow and when DIR may change; this writes it in the order the driver needs:
// the pulses stop before DIR changes, DIR is set before they start. Off when destroyed.

#include <memory>
#include <string>

#include "azt/control/step_dir.hpp"
#include "azt/linux/gpio.hpp"
#include "azt/linux/sysfs_pwm.hpp"
#include "azt/ports/axis_drive.hpp"

namespace azt::linux_os {

/// `enable` may be null (the driver's ENABLE wired on). The step output is opened at no pulses.
std::unique_ptr<ports::AxisDrive> make_step_dir_drive(SysfsPwm step,
                                                      std::unique_ptr<GpioOutput> dir,
                                                      std::unique_ptr<GpioOutput> enable,
                                                      const control::StepDirConfig& config,
                                                      std::string what);

}  // namespace azt::linux_os
