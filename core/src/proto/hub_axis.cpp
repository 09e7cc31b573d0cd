#include "azt/proto/hub_axis.hpp"

namespace azt::proto {

HubAxis hub_axis(const HubReading& reading, std::size_t axis) {
  if (axis == 0) return {reading.az_raw, reading.az_bits, reading.az_error};
  return {reading.el_raw, reading.el_bits, reading.el_error};
}

std::string hub_axis_fault(std::size_t axis, HubAxisError error) {
  return std::string(axis == 0 ? "az" : "el") +
         " encoder (EncoderHub): " + hub_axis_error_name(error);
}

}  // namespace azt::proto
