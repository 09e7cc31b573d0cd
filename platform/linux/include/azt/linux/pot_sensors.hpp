#pragma once
// Potentiometer position sensors behind the core's AxisSensor port (docs/hardware.md): a
// pot on an MCP3008 (spidev) or on an ADS1115 (i2c-dev), read through the core's PotInput
// (calibration, moving average, broken-wire and out-of-range checks). No read waits for a
// conversion: the ADS1115 converts across control ticks (Ads1115Chip).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "azt/control/pot_calibration.hpp"
#include "azt/linux/adc_devices.hpp"
#include "azt/linux/i2c_device.hpp"
#include "azt/linux/spi_device.hpp"
#include "azt/ports/axis_sensor.hpp"

namespace azt::linux_os {

/// One ADS1115, converting for the one or two axes whose pots are wired to it, in steps across
/// control ticks: a conversion takes about 8 ms at 128 samples/s and no handler may block the
/// loop, so no tick waits for one. At each tick an axis polls its channel's conversion, started
/// on an earlier tick, once; when it is done the axis fetches the result and starts the next
/// channel's conversion (its own again when it is alone on the chip), which is done long before
/// the next tick (20 Hz by default: 50 ms). So an axis alone on a chip costs 5 I2C messages a
/// tick (poll: pointer + read, fetch: pointer + read, start: one write) and no wait.
///
/// The price is latency: a reading reaches the station one tick after its conversion started
/// (≤ tick_s; two ticks with two axes on the chip, each then read every other tick), stamped
/// with the tick that fetched it, as the hub's frames are stamped when they arrive. Accepted:
/// one tick adds at most rate × tick_s of lag (3 deg/s × 50 ms = 0.15 deg), less than the pot's
/// moving average already holds (average_samples = 4: 1.5 ticks) and well inside a relay
/// window of 1 deg. Two axes on one chip need tick_hz > 15: the backend passes both axes on
/// stamped with the older, up to two ticks old then, and the stale limit is 200 ms less a tick.
class Ads1115Chip {
 public:
  /// Polls, one a tick, before a conversion counts as lost: 3 ticks are at least 15 ms at the
  /// fastest tick (200 Hz), more than 1.7 conversions even with the chip's oscillator 10% slow.
  /// At 20 Hz the first poll finds the conversion done.
  static constexpr unsigned kMaxPolls = 3;

  Ads1115Chip(std::unique_ptr<I2cBus> bus, std::uint8_t address);

  [[nodiscard]] bool has_channel(unsigned channel) const;
  void add_channel(unsigned channel) { channels_.push_back(channel); }
  /// A channel read less often than the pots' (a motor's current or temperature: they change
  /// over seconds, docs/hardware.md "Brake, current and temperature"): the slow channels take
  /// one turn, in rotation, after each round of the pots' channels, so a pot alone beside them is
  /// still read every other tick.
  void add_slow_channel(unsigned channel) { slow_.push_back(channel); }

  /// The tick `now_s` of `channel`'s axis: its new code, nullopt while there is none (the first
  /// tick, a conversion still running, the other axis's turn), or an error (a bus failure, a
  /// conversion not done after kMaxPolls ticks) after which the next step starts afresh.
  Result<std::optional<std::int16_t>> step(unsigned channel, double now_s);

 private:
  using Step = Result<std::optional<std::int16_t>>;

  Step begin(unsigned channel, double now_s);
  Step lose(Error why);
  /// The channel after `channel` in turn, the same one when it is alone.
  [[nodiscard]] unsigned next_after(unsigned channel) const;
  /// The slow channel whose turn is next.
  [[nodiscard]] unsigned next_slow() const;

  std::unique_ptr<I2cBus> bus_;
  Ads1115Reader adc_;
  std::vector<unsigned> channels_;
  std::vector<unsigned> slow_;
  std::size_t next_slow_ = 0;          ///< the slow channel whose turn is next
  std::optional<unsigned> in_flight_;  ///< the channel being converted
  double started_s_ = 0.0;             ///< the tick that started it
  unsigned polls_ = 0;                 ///< its polls so far
};

/// One SPI transfer a tick: the MCP3008 converts while it clocks the result out.
std::unique_ptr<ports::AxisSensor> make_mcp3008_pot_sensor(std::unique_ptr<SpiBus> bus,
                                                           unsigned channel,
                                                           const control::PotInputConfig& pot,
                                                           std::string what);

/// `channel` of `chip`, which another axis may share on another channel.
std::unique_ptr<ports::AxisSensor> make_ads1115_pot_sensor(std::shared_ptr<Ads1115Chip> chip,
                                                           unsigned channel,
                                                           const control::PotInputConfig& pot,
                                                           std::string what);

}  // namespace azt::linux_os
