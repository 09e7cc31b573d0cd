#pragma once
// The two potentiometer ADCs (docs/hardware.md) on the bus seams: an MCP3008 on SPI and an ADS1115
// on I2C. Only the transaction order lives here; the bytes come from proto/adc_frames.hpp and
// the OS calls from the buses, so tests run them against recording fakes.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "azt/linux/i2c_device.hpp"
#include "azt/linux/spi_device.hpp"
#include "azt/proto/adc_frames.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

/// MCP3008 (10 bits, 8 single-ended channels) in SPI mode 0: one 3-byte transfer per reading.
class Mcp3008Reader {
 public:
  explicit Mcp3008Reader(SpiBus& bus) : bus_(bus) {}

  /// The 10-bit code (0–1023) of `channel` (0–7).
  Result<std::uint16_t> read(unsigned channel);
  /// The mean code of `n` (1–256) readings in a row, against the noise of a long pot lead.
  Result<double> read_average(unsigned channel, unsigned n);

 private:
  SpiBus& bus_;
};

/// ADS1115 (16 bits, 4 single-ended channels) at one I2C address, single-shot at 128 samples/s.
/// A conversion takes about 7.8 ms (up to 10% more: the internal oscillator may run slow), far
/// longer than a handler on the event loop may block. So a reading is three steps, none of which
/// waits: start() a conversion, poll() it until it is done, fetch() the result. The caller spreads
/// them over its ticks (pot_sensors.hpp: Ads1115Chip, one poll a tick).
class Ads1115Reader {
 public:
  static constexpr std::uint8_t kDefaultAddress = 0x48;  ///< ADDR pin to GND

  explicit Ads1115Reader(I2cBus& bus, std::uint8_t address = kDefaultAddress,
                         proto::Ads1115Range range = proto::Ads1115Range::Fs4V096)
      : bus_(bus), address_(address), range_(range) {}

  /// Starts one conversion of AIN`channel` (0–3) against GND: one I2C write, of Config.
  Result<bool> start(unsigned channel);
  /// One read of the Config register (a pointer write and a read): true when the conversion
  /// last started is done (OS bit set), false while it runs. Fails if none was started.
  Result<bool> poll();
  /// Reads the Conversion register (a pointer write and a read): the result of the conversion
  /// last started, which poll() has said is done. Fails if none was started since the last fetch.
  Result<std::int16_t> fetch();

  [[nodiscard]] std::uint8_t address() const { return address_; }
  [[nodiscard]] double volts_per_count() const { return proto::ads1115_volts_per_count(range_); }
  /// An error naming the chip and the channel: "ADS1115 at 0x48 channel 2: " and `what`.
  [[nodiscard]] Error error(unsigned channel, const std::string& what) const;

 private:
  Result<bool> read_register(std::uint8_t pointer, std::array<std::uint8_t, 2>& value);

  I2cBus& bus_;
  std::uint8_t address_;
  proto::Ads1115Range range_;
  std::optional<unsigned> started_channel_;  ///< the conversion in flight, until fetched
};

}  // namespace azt::linux_os
