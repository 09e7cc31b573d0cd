#pragma once
// The bytes on the wire for the two ADCs that read potentiometers (docs/hardware.md), so the Linux
// spidev and i2c-dev adapters only move bytes. Checked against the datasheets' figures.
//
// MCP3008 (Microchip DS21295, figure 6-1): 3 bytes in SPI mode 0. Out: 0x01 (start bit), then
// SGL/DIFF, D2 D1 D0 in the top nibble of the second byte, then a don't-care byte. In: the
// 10-bit result is the low two bits of the second byte and all of the third.
//
// ADS1115 (TI SBAS444, section 8.6): write the 16-bit Config register (pointer 0x01) to start a
// single-shot conversion, poll OS until it reads 1, then read the Conversion register (pointer
// 0x00): a 16-bit two's-complement result, MSB first.

#include <array>
#include <cstdint>
#include <optional>

#include "azt/util/result.hpp"

namespace azt::proto {

/// The MCP3008 request for a single-ended read of `channel` (0–7); nullopt for other channels.
std::optional<std::array<std::uint8_t, 3>> mcp3008_request(unsigned channel);
/// The 10-bit code from the bytes clocked in with that request.
std::uint16_t mcp3008_code(const std::array<std::uint8_t, 3>& reply);

/// ADS1115 full-scale ranges (PGA), in volts.
/// Fs6V144: ±6.144 V, and so on.
enum class Ads1115Range : std::uint8_t { Fs6V144 = 0, Fs4V096 = 1, Fs2V048 = 2, Fs1V024 = 3 };

inline constexpr std::uint8_t kAds1115PointerConversion = 0x00;
inline constexpr std::uint8_t kAds1115PointerConfig = 0x01;

/// The Config value that starts one single-ended conversion of AIN`channel` (0–3) against GND at
/// 128 samples/s with the comparator off; nullopt for other channels.
std::optional<std::uint16_t> ads1115_single_shot_config(unsigned channel, Ads1115Range range);
/// The 3-byte I2C write of a register: pointer, then the value MSB first.
std::array<std::uint8_t, 3> ads1115_write(std::uint8_t pointer, std::uint16_t value);
/// True when a Config read-back says the conversion is done (OS bit set).
bool ads1115_ready(std::array<std::uint8_t, 2> config_read);
/// The signed result of a Conversion register read.
std::int16_t ads1115_code(std::array<std::uint8_t, 2> conversion_read);
/// Volts per count for a range (full scale / 32768).
double ads1115_volts_per_count(Ads1115Range range);

}  // namespace azt::proto
