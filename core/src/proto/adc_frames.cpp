#include "azt/proto/adc_frames.hpp"

namespace azt::proto {

std::optional<std::array<std::uint8_t, 3>> mcp3008_request(unsigned channel) {
  if (channel > 7) return std::nullopt;
  // SGL/DIFF = 1 (single-ended), then the channel's three bits.
  const auto control = static_cast<std::uint8_t>((0x8U | channel) << 4U);
  return std::array<std::uint8_t, 3>{0x01, control, 0x00};
}

std::uint16_t mcp3008_code(const std::array<std::uint8_t, 3>& reply) {
  return static_cast<std::uint16_t>(((reply[1] & 0x03U) << 8U) | reply[2]);
}

std::optional<std::uint16_t> ads1115_single_shot_config(unsigned channel, Ads1115Range range) {
  if (channel > 3) return std::nullopt;
  std::uint16_t c = 0;
  c |= 1U << 15U;                                                       // OS: start a conversion
  c |= static_cast<std::uint16_t>((0x4U | channel) << 12U);             // MUX: AINx vs GND
  c |= static_cast<std::uint16_t>(static_cast<unsigned>(range) << 9U);  // PGA
  c |= 1U << 8U;                                                        // MODE: single-shot
  c |= 0x4U << 5U;                                                      // DR: 128 SPS
  c |= 0x3U;                                                            // COMP_QUE: comparator off
  return c;
}

std::array<std::uint8_t, 3> ads1115_write(std::uint8_t pointer, std::uint16_t value) {
  return {pointer, static_cast<std::uint8_t>(value >> 8U),
          static_cast<std::uint8_t>(value & 0xFFU)};
}

bool ads1115_ready(std::array<std::uint8_t, 2> config_read) {
  return (config_read[0] & 0x80U) != 0;
}

std::int16_t ads1115_code(std::array<std::uint8_t, 2> conversion_read) {
  const auto raw = static_cast<std::uint16_t>((conversion_read[0] << 8U) | conversion_read[1]);
  return static_cast<std::int16_t>(raw);
}

double ads1115_volts_per_count(Ads1115Range range) {
  switch (range) {
    case Ads1115Range::Fs6V144:
      return 6.144 / 32768.0;
    case Ads1115Range::Fs4V096:
      return 4.096 / 32768.0;
    case Ads1115Range::Fs2V048:
      return 2.048 / 32768.0;
    case Ads1115Range::Fs1V024:
      return 1.024 / 32768.0;
  }
  return 0.0;
}

}  // namespace azt::proto
