#pragma once
// One axis of an EncoderHub frame, and the fault a station reports when the hub says that axis
// has no position: shared by the Linux hub sensors and the simulated station's sensors, so both
// name a fault alike. (hub_frame.hpp itself stays C++14 and heap-free for the firmware.)

#include <cstddef>
#include <cstdint>
#include <string>

#include "azt/proto/hub_frame.hpp"

namespace azt::proto {

struct HubAxis {
  std::uint16_t raw = 0;
  std::uint8_t bits = 0;
  HubAxisError error = HubAxisError::None;
};

/// Axis 0 is azimuth, 1 elevation.
HubAxis hub_axis(const HubReading& reading, std::size_t axis);

/// "az encoder (EncoderHub): no encoder answers".
std::string hub_axis_fault(std::size_t axis, HubAxisError error);

}  // namespace azt::proto
