// The `hardware` backend's ADS1115 sensor (i2c-dev) tick by tick, behind a bus that records every
// I2C message: a conversion started at one tick is read at the next, a conversion that never
// finishes and a bus error are named faults, two axes share one chip by taking turns, and a
// motor's current and temperature share a pot's chip in the pot's gaps.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_devices.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "support/hardware_station.hpp"

namespace azt::app {
namespace {

using testing::kHardwareStation;

// No wait between polls to configure: nothing waits.
template <typename P>
constexpr bool kHasAdcWait = requires(P p) {
  p.adc_wait;
};
static_assert(!kHasAdcWait<HardwarePorts>);

using Lines = std::vector<std::string>;

/// An ADS1115 behind a recording bus: each I2C message is logged ("W 48: 01 c3 83", "R 48: 2").
/// A Config write starts a conversion of the channel in its MUX bits, which holds that channel's
/// entry of `codes` as it is then; a Config read says done when `ready`.
class RecordingAds1115 final : public linux_os::I2cBus {
 public:
  std::array<int, 4> codes{};
  bool ready = true;
  std::string error;

  Result<bool> write(std::uint8_t addr, std::span<const std::uint8_t> bytes) override {
    std::string line = "W " + hex(addr) + ":";
    for (const auto b : bytes) line += " " + hex(b);
    log_.push_back(line);
    if (!error.empty()) return fail(error);
    pointer_ = bytes[0];
    if (pointer_ == 0x01 && bytes.size() == 3) {
      converted_ = codes.at(((bytes[1] >> 4U) & 0x7U) - 4U);  // MUX 1xx: AINx against GND
    }
    return true;
  }
  Result<bool> read(std::uint8_t addr, std::span<std::uint8_t> bytes) override {
    log_.push_back("R " + hex(addr) + ": " + std::to_string(bytes.size()));
    if (!error.empty()) return fail(error);
    const auto v = static_cast<std::uint16_t>(pointer_ == 0x01 ? (ready ? 0x8000 : 0) : converted_);
    bytes[0] = static_cast<std::uint8_t>(v >> 8U);
    bytes[1] = static_cast<std::uint8_t>(v & 0xFFU);
    return true;
  }
  /// The messages since the last call: one tick's.
  Lines take() { return std::exchange(log_, {}); }

 private:
  static std::string hex(std::uint8_t b) {
    const char* digits = "0123456789abcdef";
    return {digits[b >> 4U], digits[b & 0xFU]};
  }

  Lines log_;
  std::uint8_t pointer_ = 0;
  int converted_ = 0;
};

/// [hardware.el] of kHardwareStation (an ADS1115 at 0x48, channel 0, 0–26000 counts for 0–90°)
/// unaveraged, its chips recorded.
struct AdsRig {
  AdsRig() : el(daemon_config_from(ConfigFile::parse(kHardwareStation, "hw.toml")).hardware.el) {
    el.pot.average_samples = 1;
    ports.open_i2c = [this](const std::string&) -> Result<std::unique_ptr<linux_os::I2cBus>> {
      auto bus = std::make_unique<RecordingAds1115>();
      chips.push_back(bus.get());
      return std::unique_ptr<linux_os::I2cBus>(std::move(bus));
    };
  }
  /// The elevation's settings for azimuth, on `channel` at `address`.
  [[nodiscard]] HardwareAxisConfig az(unsigned channel, std::uint8_t address = 0x48) const {
    HardwareAxisConfig a = el;
    a.name = "az";
    a.adc_channel = channel;
    a.adc_address = address;
    return a;
  }

  HardwareAxisConfig el;
  HardwarePorts ports;
  std::vector<RecordingAds1115*> chips;
};

TEST(Ads1115Sensor, AConversionStartedAtOneTickIsReadAtTheNext) {
  AdsRig rig;
  auto sensor = open_adc_sensor(rig.el, rig.ports);
  ASSERT_EQ(rig.chips.size(), 1U);
  RecordingAds1115& chip = *rig.chips[0];
  const Lines start = {"W 48: 01 c3 83"};  // AIN0, ±4.096 V, single shot, 128 SPS
  const Lines poll_fetch_start = {"W 48: 01", "R 48: 2", "W 48: 00", "R 48: 2", "W 48: 01 c3 83"};

  chip.codes[0] = 13000;  // 45°
  auto first = sensor->read(0.0);
  ASSERT_TRUE(first.ok()) << first.error().message;
  EXPECT_FALSE(first.value().has_value()) << "nothing to read at the first tick";
  EXPECT_EQ(chip.take(), start);

  chip.codes[0] = 26000;  // moved on after tick 0's conversion: in tick 1's, not in this one
  auto second = sensor->read(0.05);
  ASSERT_TRUE(second.ok()) << second.error().message;
  ASSERT_TRUE(second.value().has_value());
  EXPECT_DOUBLE_EQ(second.value()->deg, 45.0);
  EXPECT_EQ(chip.take(), poll_fetch_start);

  auto third = sensor->read(0.10);
  ASSERT_TRUE(third.ok() && third.value().has_value());
  EXPECT_DOUBLE_EQ(third.value()->deg, 90.0);
  EXPECT_EQ(chip.take(), poll_fetch_start);
}

TEST(Ads1115Sensor, NeverReadyIsAnErrorAtTheThirdPollThenItStartsAgain) {
  AdsRig rig;
  auto sensor = open_adc_sensor(rig.el, rig.ports);
  RecordingAds1115& chip = *rig.chips[0];
  chip.ready = false;
  chip.codes[0] = 13000;
  ASSERT_TRUE(sensor->read(0.0).ok());
  EXPECT_EQ(chip.take().size(), 1U);  // start
  for (const double t : {0.05, 0.10}) {
    auto pending = sensor->read(t);
    ASSERT_TRUE(pending.ok()) << "at " << t << ": " << pending.error().message;
    EXPECT_FALSE(pending.value().has_value());
    EXPECT_EQ(chip.take(), (Lines{"W 48: 01", "R 48: 2"})) << "one poll at " << t;
  }
  auto lost = sensor->read(0.15);
  ASSERT_FALSE(lost.ok());
  EXPECT_EQ(lost.error().message, "ADS1115 at 0x48 channel 0: conversion not done after 3 ticks");
  EXPECT_EQ(chip.take(), (Lines{"W 48: 01", "R 48: 2"})) << "the Conversion is never read";

  chip.ready = true;
  auto restart = sensor->read(0.20);
  ASSERT_TRUE(restart.ok());
  EXPECT_FALSE(restart.value().has_value());
  EXPECT_EQ(chip.take(), (Lines{"W 48: 01 c3 83"}));
  auto back = sensor->read(0.25);
  ASSERT_TRUE(back.ok() && back.value().has_value());
  EXPECT_DOUBLE_EQ(back.value()->deg, 45.0);
}

TEST(Ads1115Sensor, ABusErrorIsReportedAtItsTickAndTheNextStartsAgain) {
  AdsRig rig;
  auto sensor = open_adc_sensor(rig.el, rig.ports);
  RecordingAds1115& chip = *rig.chips[0];
  chip.codes[0] = 26000;
  ASSERT_TRUE(sensor->read(0.0).ok());
  chip.error = "/dev/i2c-1 addr 0x48: Remote I/O error (nothing answers at this address?)";
  (void)chip.take();
  auto r = sensor->read(0.05);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "ADS1115 at 0x48 channel 0: " + chip.error);
  EXPECT_EQ(chip.take().size(), 1U) << "stops at the failed pointer write";
  chip.error.clear();
  auto restart = sensor->read(0.10);
  ASSERT_TRUE(restart.ok());
  EXPECT_FALSE(restart.value().has_value());
  auto back = sensor->read(0.15);
  ASSERT_TRUE(back.ok() && back.value().has_value());
  EXPECT_DOUBLE_EQ(back.value()->deg, 90.0);
}

TEST(Ads1115Sensor, TwoAxesOnOneChipTakeTurnsAndNeverGetEachOthersChannel) {
  AdsRig rig;
  auto az = open_adc_sensor(rig.az(1), rig.ports);  // the backend's order: az, then el
  auto el = open_adc_sensor(rig.el, rig.ports);
  ASSERT_EQ(rig.chips.size(), 1U) << "one chip, opened once";
  RecordingAds1115& chip = *rig.chips[0];
  chip.codes = {13000, 26000, 0, 0};  // el on AIN0: 45°, az on AIN1: 90°
  std::vector<std::string> got;       // per tick: which axes had a reading
  for (int tick = 0; tick < 8; ++tick) {
    const double t = 0.05 * tick;
    auto a = az->read(t);
    auto e = el->read(t);
    ASSERT_TRUE(a.ok() && e.ok()) << "tick " << tick;
    if (a.value()) {
      EXPECT_DOUBLE_EQ(a.value()->deg, 90.0);
    }
    if (e.value()) {
      EXPECT_DOUBLE_EQ(e.value()->deg, 45.0);
    }
    got.push_back(std::string(a.value() ? "a" : "") + (e.value() ? "e" : ""));
    EXPECT_LE(chip.take().size(), 5U) << "tick " << tick;
  }
  EXPECT_EQ(got, (Lines{"", "a", "e", "a", "e", "a", "e", "a"}));
}

TEST(Ads1115Sensor, TwoAxesOnOneChannelAreRefusedAndTwoAddressesAreTwoChips) {
  AdsRig rig;
  auto el = open_adc_sensor(rig.el, rig.ports);
  try {
    (void)open_adc_sensor(rig.az(0), rig.ports);
    FAIL() << "two axes on AIN0";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[hardware.az] adc_channel"), std::string::npos)
        << e.what();
  }
  auto az = open_adc_sensor(rig.az(0, 0x49), rig.ports);
  EXPECT_EQ(rig.chips.size(), 2U);
}

/// The elevation's pot with its motor's current (AIN1, 10 A per volt) and temperature (AIN2, an
/// LM35) on the same ADS1115.
HardwareAxisConfig with_motor(HardwareAxisConfig a) {
  a.motor_adc = MotorAdcKind::Ads1115;
  a.motor_adc_device = a.adc_device;
  a.motor_adc_address = a.adc_address;
  a.current_adc_channel = 1;
  a.current.amps_per_volt = 10.0;
  a.temperature_adc_channel = 2;
  a.trips.current_limit_a = 5.0;
  a.trips.temperature_limit_c = 75.0;
  return a;
}

TEST(Ads1115Sensor, AMotorsChannelsTakeTheTurnsBetweenThePotsReadings) {
  AdsRig rig;
  const HardwareAxisConfig el = with_motor(rig.el);
  auto pot = open_adc_sensor(el, rig.ports);  // the backend's order: sensors, then motors
  auto motor = open_motor_sensor(el, rig.ports);
  ASSERT_EQ(rig.chips.size(), 1U) << "the pot's chip, shared";
  EXPECT_EQ(motor->describe(), "el motor (ADS1115 /dev/i2c-1 at 0x48)");
  RecordingAds1115& chip = *rig.chips[0];
  chip.codes = {13000, 8000, 4000, 0};  // 45°; 1.000 V: 10 A; 0.500 V: 50 °C
  std::vector<std::string> got;         // per tick: the pot, the current, the temperature
  for (int tick = 0; tick < 10; ++tick) {
    const double t = 0.05 * tick;
    auto p = pot->read(t);
    auto m = motor->read(t);
    ASSERT_TRUE(p.ok() && m.ok()) << "tick " << tick;
    if (p.value()) {
      EXPECT_DOUBLE_EQ(p.value()->deg, 45.0);
    }
    if (m.value().current_a) {
      EXPECT_DOUBLE_EQ(*m.value().current_a, 10.0);
    }
    if (m.value().temperature_c) {
      EXPECT_DOUBLE_EQ(*m.value().temperature_c, 50.0);
    }
    got.push_back(std::string(p.value() ? "p" : "") + (m.value().current_a ? "c" : "") +
                  (m.value().temperature_c ? "t" : ""));
    EXPECT_LE(chip.take().size(), 5U) << "tick " << tick << ": never more than one conversion";
  }
  // The pot every other tick, as beside another axis's pot; each motor input every fourth.
  EXPECT_EQ(got, (Lines{"", "p", "c", "p", "t", "p", "c", "p", "t", "p"}));
}

TEST(Ads1115Sensor, AMotorsConversionThatNeverEndsIsItsReadError) {
  AdsRig rig;
  HardwareAxisConfig el = with_motor(rig.el);
  el.adc_address = 0x49;  // the pot on another chip: the motor's inputs alone on theirs
  auto motor = open_motor_sensor(el, rig.ports);
  ASSERT_EQ(rig.chips.size(), 1U);
  rig.chips[0]->codes = {0, 8000, 4000, 0};
  ASSERT_TRUE(motor->read(0.0).ok());
  auto current = motor->read(0.05);
  ASSERT_TRUE(current.ok() && current.value().current_a);
  EXPECT_FALSE(current.value().temperature_c) << "its conversion started at this tick";
  auto temperature = motor->read(0.10);
  ASSERT_TRUE(temperature.ok() && temperature.value().temperature_c);
  EXPECT_FALSE(temperature.value().current_a);
  rig.chips[0]->ready = false;
  for (const double t : {0.15, 0.20}) ASSERT_TRUE(motor->read(t).ok()) << t;
  auto lost = motor->read(0.25);
  ASSERT_FALSE(lost.ok());
  EXPECT_EQ(lost.error().message,
            "el motor (ADS1115 /dev/i2c-1 at 0x48): ADS1115 at 0x48 channel 1: conversion not "
            "done after 3 ticks");
}

TEST(Ads1115Sensor, AMotorInputOnAChannelAnotherAxisReadsIsRefusedByItsKey) {
  AdsRig rig;
  auto az = open_adc_sensor(rig.az(1), rig.ports);
  try {
    (void)open_motor_sensor(with_motor(rig.el), rig.ports);
    FAIL() << "the elevation's current on the azimuth pot's AIN1";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[hardware.el] current_adc_channel: channel 1 of this "
                                         "ADS1115 is read already"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace azt::app
