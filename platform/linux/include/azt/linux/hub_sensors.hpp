#pragma once
// The EncoderHub's two encoders behind the core's AxisSensor port: one serial link
// (HubSerialLink) whose frames both axes' sensors report. The hub sends its jumpers' bit
// resolution in every frame: a frame whose bits are not the mount's is never read as an angle,
// and the sensor latches a fault naming both until the operator clears it.

#include <array>
#include <cstdint>
#include <memory>

#include "azt/linux/asio.hpp"
#include "azt/linux/hub_serial_link.hpp"
#include "azt/ports/axis_sensor.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

struct HubSensorsConfig {
  HubSerialConfig link;
  std::array<std::uint8_t, 2> mount_bits{};  ///< [mount.az|el] encoder_bits
  /// The axes read through the hub; an axis not read (its pot on an ADC) is not checked.
  std::array<bool, 2> used{true, true};
};

/// Azimuth first, then elevation; a sensor for an axis not `used` is null. Fails naming the
/// device when it cannot be opened now.
Result<std::array<std::unique_ptr<ports::AxisSensor>, 2>> open_hub_sensors(
    boost::asio::io_context& io, const HubSensorsConfig& config);

}  // namespace azt::linux_os
