#pragma once
// The schema's key tables, one function per concern (config_schema.hpp). Each returns its
// sections in the reference's order; config_schema.cpp puts them together.

#include <span>

#include "config/config_schema.hpp"

namespace azt::app {

/// A number key with its unit, range, default and help: the shape most of the tables' keys have.
constexpr KeySpec number_key(std::string_view key, std::string_view unit, Range range,
                             std::string_view default_toml, std::string_view help) {
  return {.key = key,
          .type = KeyType::Number,
          .unit = unit,
          .range = range,
          .default_toml = default_toml,
          .help = help};
}

std::span<const SectionSpec> sky_sections();         ///< [station], [sky], [atmosphere]
std::span<const SectionSpec> control_sections();     ///< [control], [geometry], [corrections], …
std::span<const SectionSpec> target_sections();      ///< [target], [satellites], [[spacecraft]]
std::span<const SectionSpec> schedule_sections();    ///< [[schedule]]
std::span<const SectionSpec> hooks_sections();       ///< [hooks]
std::span<const SectionSpec> antenna_sections();     ///< [antenna], [hamlib], [hub], [pwm]
std::span<const SectionSpec> hardware_sections();    ///< [hardware.power], [hardware.az|el|pol]
std::span<const SectionSpec> station_io_sections();  ///< [gpio], [sequencer]
std::span<const SectionSpec> server_sections();      ///< [rotctld], [[serial]], [web], …
std::span<const SectionSpec> service_sections();     ///< [gps], [time], [receiver], [export]
std::span<const SectionSpec> sim_sections();         ///< [sim] and its tables
std::span<const SectionSpec> radio_sections();  ///< [radio], [[satellites.transmitter]], [wsjtx]

}  // namespace azt::app
