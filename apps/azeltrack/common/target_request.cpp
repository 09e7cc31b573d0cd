#include "common/target_request.hpp"

namespace azt::app {

TargetRequest target_from_name(std::string_view name) {
  if (name.substr(0, kSatellitePrefix.size()) == kSatellitePrefix) {
    return SatelliteTarget{std::string(name.substr(kSatellitePrefix.size()))};
  }
  return NamedTarget{std::string(name)};
}

std::string satellite_display_name(std::string_view catalogue_name) {
  return std::string(kSatellitePrefix) + std::string(catalogue_name);
}

}  // namespace azt::app
