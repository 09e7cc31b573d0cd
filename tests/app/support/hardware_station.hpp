#pragma once
// The station the `hardware` backend's tests run (tests/app/antenna/hardware_backend_test.cpp,
// ads1115_sensor_test.cpp): azimuth on relays read by a pot on an MCP3008 (spidev), elevation by a
// rotator box whose control pot is an MCP41010 (spidev) read by a pot on an ADS1115 (i2c-dev);
// and a dish's elevation on a linear actuator read by its feedback pot.

#include <string>

namespace azt::app::testing {

/// The file's top: the station, no target, the `hardware` backend.
inline const std::string kHardwareTop = R"([station]
grid = "FN06HE"
[target]
name = "stop"
[antenna]
backend = "hardware"
)";

/// Azimuth on relays read by a pot on an MCP3008 (spidev).
inline const std::string kHardwareAz = R"([hardware.az]
drive = "relay"
relay_forward = 5
relay_reverse = 6
window_deg = 1.0
lsb_deg = 0.44
coast_deg = 0.2
sensor = "mcp3008"
adc_device = "/dev/spidev0.1"
pot_calibration = [0, 0.0, 1023, 450.0]
open_below_counts = 3
)";

inline const std::string kHardwareStation = kHardwareTop + R"([mount.az]
max_rate_deg_s = 3.0
[mount.el]
max_rate_deg_s = 2.0
[sim.az]
start_deg = 100.0
[sim.el]
start_deg = 10.0
)" + kHardwareAz + R"([hardware.el]
drive = "pot"
spi_device = "/dev/spidev0.0"
wiper_calibration = [0, 0.0, 255, 180.0]
setpoint_band_deg = 1.5
sensor = "ads1115"
adc_device = "/dev/i2c-1"
pot_calibration = [0, 0.0, 26000, 90.0]
)";

/// The elevation of a dish on the worked example's actuator (docs/hardware.md "Linear actuators")
/// on relays, read by a feedback pot on an MCP3008: 100 counts retracted (520 mm), 900 extended
/// (977.2 mm), so 0.5715 mm a count, 0.08° to 0.18° a count along the stroke (0.1433 to
/// 0.3086 °/mm). Tests: config/hardware_config_test.cpp, antenna/actuator_pot_test.cpp.
inline const std::string kActuatorPotEl = R"([hardware.el]
drive = "relay"
relay_forward = 7
relay_reverse = 8
sensor = "mcp3008"
adc_device = "/dev/spidev0.2"
pot_calibration_mm = [100, 520.0, 900, 977.2]
actuator_pivot_to_fixed_mm = 650.0
actuator_pivot_to_moving_mm = 400.0
actuator_offset_deg = 48.0
actuator_retracted_mm = 520.0
actuator_extended_mm = 977.2
actuator_extend = "raises"
)";

}  // namespace azt::app::testing
