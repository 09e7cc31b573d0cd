#pragma once
// The two potentiometer ADCs of issue 6 §2 on the bus seams: an MCP3008 on SPI and an ADS1115
// on I2C. Only the transaction order lives here; the bytes come from proto/adc_frames.hpp and
// the OS calls from the buses, so tests run them against recording fakes.

#include <array>
#include <cstdint>
#include <functional>
#include <utility>

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
class Ads1115Reader {
 public:
  static constexpr std::uint8_t kDefaultAddress = 0x48;  ///< ADDR pin to GND
  /// Ready polls before giving up: with a 1 ms wait, about 2.5 conversion times (7.8 ms each,
  /// and the ADS1115's oscillator may run 10% slow).
  static constexpr unsigned kMaxPolls = 20;

  /// `wait_between_polls` runs between two ready polls (sleep_one_ms on hardware; tests pass a
  /// no-op). An empty function waits not at all.
  explicit Ads1115Reader(I2cBus& bus, std::uint8_t address = kDefaultAddress,
                         proto::Ads1115Range range = proto::Ads1115Range::Fs4V096,
                         std::function<void()> wait_between_polls = sleep_one_ms)
      : bus_(bus), address_(address), range_(range), wait_(std::move(wait_between_polls)) {}

  /// One conversion of AIN`channel` (0–3) against GND: write Config (starting it), poll the
  /// Config register's OS bit until it is done (at most kMaxPolls reads), read Conversion.
  Result<std::int16_t> read(unsigned channel);

  [[nodiscard]] std::uint8_t address() const { return address_; }
  [[nodiscard]] double volts_per_count() const { return proto::ads1115_volts_per_count(range_); }

 private:
  Result<bool> read_register(std::uint8_t pointer, std::array<std::uint8_t, 2>& value);

  I2cBus& bus_;
  std::uint8_t address_;
  proto::Ads1115Range range_;
  std::function<void()> wait_;
};

}  // namespace azt::linux_os
