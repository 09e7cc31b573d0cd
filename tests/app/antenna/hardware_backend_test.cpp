// The `hardware` backend with simulated devices behind its Linux-shaped ports
// (docs/hardware.md): azimuth on relays (GPIO) read by a pot on an MCP3008 (spidev), elevation by a
// rotator box whose control pot is an MCP41010 (spidev) read by a pot on an ADS1115 (i2c-dev). The
// devices answer with the simulated plants' angles; time is virtual (the backend's tick clock).
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "antenna/antenna_backend.hpp"
#include "antenna/axis_devices.hpp"
#include "azt/sim/axis_plant.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "support/fake_gpio.hpp"

namespace azt::app {
namespace {

/// An SPI chip on one chip-select: the MCP3008 answers reads, the MCP41010 records frames.
class SimSpi final : public linux_os::SpiBus {
 public:
  std::function<int(unsigned channel)> mcp3008;  ///< set: acts as an MCP3008
  std::vector<std::vector<std::uint8_t>> frames;
  bool broken = false;

  Result<bool> transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) override {
    if (broken) return fail("spidev: Input/output error");
    frames.emplace_back(tx.begin(), tx.end());
    if (mcp3008 && tx.size() == 3 && rx.size() == 3) {
      const auto code = static_cast<unsigned>(std::clamp(mcp3008((tx[1] >> 4) & 0x7U), 0, 1023));
      rx[0] = 0;
      rx[1] = static_cast<std::uint8_t>((code >> 8) & 0x3U);
      rx[2] = static_cast<std::uint8_t>(code & 0xFFU);
    }
    return true;
  }
};

/// An ADS1115: a conversion is ready at the first poll (unless not `ready`) and reads `code`.
class SimI2c final : public linux_os::I2cBus {
 public:
  std::function<int()> code;
  std::uint8_t pointer = 0;
  bool ready = true;
  int messages = 0;
  Result<bool> write(std::uint8_t /*addr*/, std::span<const std::uint8_t> bytes) override {
    ++messages;
    if (!bytes.empty()) pointer = bytes[0];
    return true;
  }
  Result<bool> read(std::uint8_t /*addr*/, std::span<std::uint8_t> bytes) override {
    ++messages;
    const int v = pointer == 0x01 ? (ready ? 0x8000 : 0) : std::clamp(code(), -32768, 32767);
    const auto u = static_cast<std::uint16_t>(v);
    bytes[0] = static_cast<std::uint8_t>(u >> 8);
    bytes[1] = static_cast<std::uint8_t>(u & 0xFFU);
    return true;
  }
};

const char* const kStation = R"([station]
grid = "FN06HE"
[target]
name = "stop"
[antenna]
backend = "hardware"
[mount.az]
max_rate_deg_s = 3.0
[mount.el]
max_rate_deg_s = 2.0
[sim.az]
start_deg = 100.0
[sim.el]
start_deg = 10.0
[hardware.az]
drive = "relay"
relay_forward = 5
relay_reverse = 6
window_deg = 1.0
lsb_deg = 0.44
coast_deg = 0.2
sensor = "mcp3008"
adc_device = "/dev/spidev0.1"
pot_calibration = [0, 0.0, 1023, 450.0]
open_below_counts = 3
[hardware.el]
drive = "pot"
spi_device = "/dev/spidev0.0"
wiper_calibration = [0, 0.0, 255, 180.0]
setpoint_band_deg = 1.5
sensor = "ads1115"
adc_device = "/dev/i2c-1"
pot_calibration = [0, 0.0, 26000, 90.0]
)";

struct Rig {
  explicit Rig(const std::string& extra = "")
      : config(daemon_config_from(ConfigFile::parse(kStation + extra, "hw.toml"))),
        az(config.sim.az),
        el(config.sim.el) {
    ports.gpio = &gpio;
    ports.open_spi = [this](const std::string& path,
                            std::uint32_t) -> Result<std::unique_ptr<linux_os::SpiBus>> {
      if (missing == path) return fail(path + ": No such file or directory");
      auto bus = std::make_unique<SimSpi>();
      if (path == "/dev/spidev0.1") {
        bus->mcp3008 = [this](unsigned) { return pot_az_code(); };
        az_adc = bus.get();
      } else {
        pot = bus.get();
      }
      return std::unique_ptr<linux_os::SpiBus>(std::move(bus));
    };
    ports.open_i2c = [this](const std::string& path) -> Result<std::unique_ptr<linux_os::I2cBus>> {
      if (missing == path) return fail(path + ": No such file or directory");
      auto bus = std::make_unique<SimI2c>();
      bus->code = [this] { return static_cast<int>(std::lround(el.shaft_deg() / 90.0 * 26000.0)); };
      el_adc = bus.get();
      return std::unique_ptr<linux_os::I2cBus>(std::move(bus));
    };
  }

  std::unique_ptr<AntennaBackend> open() { return make_hardware_backend(io, config, ports); }

  int pot_az_code() const {
    if (az_wire_open) return 0;
    return static_cast<int>(std::lround(az.shaft_deg() / 450.0 * 1023.0));
  }
  [[nodiscard]] bool relay(const char* key) const {
    const auto it = gpio.outputs.find(key);
    return it != gpio.outputs.end() && it->second;
  }
  /// The plants for one tick: the azimuth motor follows its relays, the rotator box drives the
  /// elevation towards the angle of the wiper it was last sent, beyond its own 0.5° deadband.
  void step_plants(double dt) {
    const bool fwd = relay("[hardware.az] relay_forward");
    const bool rev = relay("[hardware.az] relay_reverse");
    both_relays_on = both_relays_on || (fwd && rev);
    az.step(fwd ? 1.0 : rev ? -1.0 : 0.0, dt);
    if (pot != nullptr && !pot->frames.empty()) {
      const double setpoint = pot->frames.back()[1] / 255.0 * 180.0;
      const double error = setpoint - el.shaft_deg();
      el.step(std::fabs(error) > 0.5 ? std::copysign(1.0, error) : 0.0, dt);
    } else {
      el.step(0.0, dt);
    }
  }
  void run(AntennaBackend& a, const control::Demand& demand, double seconds) {
    for (const double end = t + seconds; t < end; t += 0.05) {
      step_plants(0.05);
      a.tick(t, demand, control::AzEl{});
    }
  }

  boost::asio::io_context io;
  DaemonConfig config;
  testing::FakeGpio gpio{io};
  HardwarePorts ports;
  sim::AxisPlant az;
  sim::AxisPlant el;
  SimSpi* pot = nullptr;
  SimSpi* az_adc = nullptr;
  SimI2c* el_adc = nullptr;
  std::string missing;
  bool az_wire_open = false;
  bool both_relays_on = false;
  double t = 0.0;
};

TEST(HardwareBackend, RelaysOnAPotAndARotatorBoxReachTheTarget) {
  Rig rig;
  auto backend = rig.open();
  EXPECT_NE(backend->describe().find("relays"), std::string::npos) << backend->describe();
  EXPECT_NE(backend->describe().find("MCP41010"), std::string::npos) << backend->describe();
  control::Demand go;
  go.position = control::AzEl{140.0, 40.0};
  rig.run(*backend, go, 60.0);
  EXPECT_NEAR(rig.az.shaft_deg(), 140.0, 1.0 + 0.44 + 0.5);  // window + pot step + coast
  EXPECT_NEAR(rig.el.shaft_deg(), 40.0, 0.71 + 0.5);         // wiper step + the box's band
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  EXPECT_FALSE(rig.both_relays_on);
  // Bit-exact MCP41010 frames, written only when the code changes.
  ASSERT_NE(rig.pot, nullptr);
  ASSERT_FALSE(rig.pot->frames.empty());
  for (std::size_t i = 0; i < rig.pot->frames.size(); ++i) {
    ASSERT_EQ(rig.pot->frames[i].size(), 2U);
    EXPECT_EQ(rig.pot->frames[i][0], 0x11);
    if (i > 0) {
      EXPECT_NE(rig.pot->frames[i][1], rig.pot->frames[i - 1][1]) << "resent unchanged";
    }
  }
  EXPECT_EQ(rig.pot->frames.back()[1],
            static_cast<std::uint8_t>(std::lround(40.0 / 180.0 * 255.0)));
  // A relay never closes on the other direction without an open tick between.
  const auto& w = rig.gpio.writes;
  for (std::size_t i = 1; i < w.size(); ++i) {
    if (w[i].active && w[i - 1].active) {
      EXPECT_EQ(w[i].key, w[i - 1].key);
    }
  }
  const auto report = backend->position(rig.t);
  ASSERT_TRUE(report.has_value());
  EXPECT_NEAR(report->az_deg, 140.0, 2.0);
}

TEST(HardwareBackend, AnOpenPotWireStopsTheDriveAndIsNamed) {
  Rig rig;
  auto backend = rig.open();
  control::Demand go;
  go.position = control::AzEl{160.0, 10.0};
  rig.run(*backend, go, 3.0);
  ASSERT_TRUE(rig.relay("[hardware.az] relay_forward"));
  rig.az_wire_open = true;  // reads 0 counts: below open_below_counts
  rig.run(*backend, go, 0.5);
  EXPECT_FALSE(rig.relay("[hardware.az] relay_forward")) << "driven on a broken pot";
  ASSERT_FALSE(backend->faults().empty());
  EXPECT_NE(backend->faults().back().find("az pot"), std::string::npos) << backend->faults().back();
  EXPECT_FALSE(backend->position(rig.t).has_value());
  rig.az_wire_open = false;
  rig.run(*backend, go, 3.0);
  EXPECT_TRUE(backend->position(rig.t).has_value()) << "did not recover when the wire came back";
}

TEST(HardwareBackend, AnAds1115HasNoReadingAtTheFirstTickWhichIsNotAFault) {
  // The conversion started at the first tick is read at the second: until then the elevation
  // is a sensor that has not reported yet, as a hub before its first frame.
  Rig rig;
  auto backend = rig.open();
  control::Demand go;
  go.position = control::AzEl{100.0, 30.0};
  backend->tick(0.0, go, control::AzEl{});
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  EXPECT_FALSE(backend->position(0.0).has_value());
  EXPECT_FALSE(backend->encoder_reading().has_value());
  backend->tick(0.05, go, control::AzEl{});
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  ASSERT_TRUE(backend->encoder_reading().has_value());
  EXPECT_NEAR(backend->encoder_reading()->el_deg, 10.0, 0.01);
}

TEST(HardwareBackend, AnAds1115ThatNeverFinishesIsANamedSensorFaultAndRecovers) {
  Rig rig;
  auto backend = rig.open();
  control::Demand go;
  go.position = control::AzEl{100.0, 30.0};
  rig.run(*backend, go, 1.0);
  ASSERT_TRUE(backend->faults().empty()) << backend->faults().front();
  ASSERT_NE(rig.el_adc, nullptr);
  rig.el_adc->ready = false;
  for (const double end = rig.t + 0.5; rig.t < end; rig.t += 0.05) {
    rig.step_plants(0.05);
    const int before = rig.el_adc->messages;
    backend->tick(rig.t, go, control::AzEl{});
    EXPECT_LE(rig.el_adc->messages - before, 2) << "a pending conversion: one poll a tick";
  }
  const auto faults = backend->faults();
  ASSERT_FALSE(faults.empty());
  EXPECT_NE(faults.back().find("ADS1115 at 0x48 channel 0: conversion not done after 3 ticks"),
            std::string::npos)
      << faults.back();
  EXPECT_FALSE(backend->position(rig.t).has_value()) << "the elevation went stale";
  rig.el_adc->ready = true;
  rig.run(*backend, go, 1.0);
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  EXPECT_TRUE(backend->position(rig.t).has_value()) << "did not recover";
}

TEST(HardwareBackend, AnAds1115TakesAtMostFiveI2cMessagesATick) {
  // Poll (pointer, read), fetch (pointer, read), start (one write): no polling loop in a tick.
  Rig rig;
  auto backend = rig.open();
  control::Demand go;
  go.position = control::AzEl{120.0, 40.0};
  std::map<int, int> ticks_with;  // messages in a tick -> ticks
  for (int tick = 0; tick < 100; ++tick, rig.t += 0.05) {
    rig.step_plants(0.05);
    const int before = rig.el_adc->messages;
    backend->tick(rig.t, go, control::AzEl{});
    ++ticks_with[rig.el_adc->messages - before];
  }
  EXPECT_EQ(ticks_with, (std::map<int, int>{{1, 1}, {5, 99}})) << "the first tick only starts";
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
}

TEST(HardwareBackend, AnSpiWriteFailureIsADriveFault) {
  Rig rig;
  auto backend = rig.open();
  control::Demand go;
  go.position = control::AzEl{100.0, 30.0};
  rig.run(*backend, go, 1.0);
  rig.pot->broken = true;
  go.position = control::AzEl{100.0, 50.0};
  rig.run(*backend, go, 1.0);
  ASSERT_FALSE(backend->faults().empty());
  bool named = false;
  for (const auto& f : backend->faults()) named = named || f.find("el drive") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(HardwareBackend, MissingDevicesNameTheirKeysAndLeaveNothingEnergized) {
  for (const std::string device : {"/dev/spidev0.0", "/dev/spidev0.1", "/dev/i2c-1"}) {
    Rig rig;
    rig.missing = device;
    try {
      (void)rig.open();
      FAIL() << "opened without " << device;
    } catch (const UsageError& e) {
      const std::string key = device == "/dev/spidev0.0"   ? "[hardware.el] spi_device"
                              : device == "/dev/spidev0.1" ? "[hardware.az] adc_device"
                                                           : "[hardware.el] adc_device";
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
    EXPECT_FALSE(rig.relay("[hardware.az] relay_forward"));
  }
  Rig busy;
  busy.gpio.make_busy(6);
  try {
    (void)busy.open();
    FAIL() << "opened with a busy relay line";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[hardware.az] relay_reverse"), std::string::npos)
        << e.what();
  }
}

TEST(HardwareBackend, PowerAndPolarityRelaysNeverSwitchPolarityUnderPower) {
  const std::string el = R"([hardware.el]
drive = "relay"
relay_power = 7
relay_polarity = 8
window_deg = 1.0
lsb_deg = 0.01
sensor = "ads1115"
adc_device = "/dev/i2c-1"
pot_calibration = [0, 0.0, 26000, 90.0]
)";
  std::string text = kStation;
  text = text.substr(0, text.find("[hardware.el]")) + el;
  Rig rig;
  rig.config = daemon_config_from(ConfigFile::parse(text, "pp.toml"));
  auto backend = rig.open();
  // The actuator follows power, in the polarity's direction.
  control::Demand up;
  up.position = control::AzEl{100.0, 30.0};
  control::Demand down;
  down.position = control::AzEl{100.0, 5.0};
  for (int leg = 0; leg < 4; ++leg) {
    const control::Demand& d = leg % 2 == 0 ? up : down;
    for (const double end = rig.t + 20.0; rig.t < end; rig.t += 0.05) {
      const bool power = rig.relay("[hardware.el] relay_power");
      const bool reverse = rig.relay("[hardware.el] relay_polarity");
      rig.el.step(power ? (reverse ? -1.0 : 1.0) : 0.0, 0.05);
      rig.az.step(0.0, 0.05);
      backend->tick(rig.t, d, control::AzEl{});
    }
  }
  EXPECT_NEAR(rig.el.shaft_deg(), 5.0, 1.5);
  bool power = false;
  int polarity_changes = 0;
  for (const auto& w : rig.gpio.writes) {
    if (w.key == "[hardware.el] relay_power") power = w.active;
    if (w.key == "[hardware.el] relay_polarity") {
      ++polarity_changes;
      EXPECT_FALSE(power) << "polarity switched with power on";
    }
  }
  EXPECT_GE(polarity_changes, 3);
}

// ---- the ADS1115 sensor, tick by tick -------------------------------------------------------

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

/// [hardware.el] of kStation (an ADS1115 at 0x48, channel 0, 0–26000 counts for 0–90°)
/// unaveraged, its chips recorded.
struct AdsRig {
  AdsRig() : el(daemon_config_from(ConfigFile::parse(kStation, "hw.toml")).hardware.el) {
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

TEST(HardwareConfig, MistakesNameTheKey) {
  const auto error_of = [](const std::string& extra) {
    try {
      (void)daemon_config_from(ConfigFile::parse(
          "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"hardware\"\n[hub]\ndevice = "
          "\"/dev/null\"\n" +
              extra,
          "c.toml"));
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error_of(""), "");
  EXPECT_NE(
      error_of("[hardware.az]\ndrive = \"relay\"\nrelay_forward = 5\n").find("[hardware.az].drive"),
      std::string::npos);
  EXPECT_NE(error_of("[hardware.el]\ndrive = \"pot\"\nspi_device = \"/dev/spidev0.0\"\n")
                .find("[hardware.el].wiper_calibration"),
            std::string::npos);
  EXPECT_NE(error_of("[hardware.az]\nsensor = \"mcp3008\"\nadc_device = \"/dev/spidev0.1\"\n")
                .find("[hardware.az].pot_calibration"),
            std::string::npos);
  EXPECT_NE(error_of("[hardware.az]\nsensor = \"ads1115\"\nadc_device = \"/dev/i2c-1\"\n"
                     "adc_channel = 4\npot_calibration = [0, 0, 100, 90]\n")
                .find("[hardware.az].adc_channel"),
            std::string::npos);
  EXPECT_NE(error_of("[hardware.az]\ndrive = \"stepper\"\n").find("[hardware.az].drive must be"),
            std::string::npos);
  EXPECT_NE(error_of("[gpio]\nestop = 5\n[hardware.az]\ndrive = \"relay\"\nrelay_forward = 5\n"
                     "relay_reverse = 6\n")
                .find("same line as [gpio] estop"),
            std::string::npos);
  // Numbers are checked before they are narrowed: 4294967297 is not 1 (docs/reliability.md
  // "Hardening" row 9).
  const std::string pot =
      "[hardware.az]\nsensor = \"mcp3008\"\nadc_device = \"/dev/spidev0.1\"\n"
      "pot_calibration = [0, 0, 1000, 450]\n";
  EXPECT_EQ(error_of(pot + "open_below_counts = 1\n"), "");
  EXPECT_NE(
      error_of(pot + "open_below_counts = 4294967297\n").find("[hardware.az].open_below_counts"),
      std::string::npos);
  EXPECT_NE(
      error_of(pot + "open_above_counts = -4294967295\n").find("[hardware.az].open_above_counts"),
      std::string::npos);
  EXPECT_NE(error_of(pot + "average_samples = -1\n").find("[hardware.az].average_samples"),
            std::string::npos);
}

}  // namespace
}  // namespace azt::app
