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
#include "support/hardware_station.hpp"

namespace azt::app {
namespace {

using testing::kHardwareStation;

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

/// Azimuth alone, as kHardwareStation's; the elevation fixed at 0 ([mount.el] fixed_deg).
const std::string kAzimuthOnly = testing::kHardwareTop + R"([mount.az]
max_rate_deg_s = 3.0
[mount.el]
fixed_deg = 0.0
[sim.az]
start_deg = 100.0
)" + testing::kHardwareAz;

struct Rig {
  explicit Rig(const std::string& extra = "", const std::string& station = kHardwareStation)
      : config(daemon_config_from(ConfigFile::parse(station + extra, "hw.toml"))),
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

TEST(HardwareBackend, AnAzimuthOnlyStationOpensNoElevationDeviceAndTurnsInAzimuth) {
  Rig rig("", kAzimuthOnly);
  auto backend = rig.open();
  EXPECT_EQ(rig.pot, nullptr);  // neither the rotator box's pot nor the ADS1115 was opened
  EXPECT_EQ(rig.el_adc, nullptr);
  EXPECT_NE(backend->describe().find("el: fixed"), std::string::npos) << backend->describe();
  control::Demand go;
  go.position = control::AzEl{140.0, 40.0};  // a PC program's elevation: not this station's
  rig.run(*backend, go, 60.0);
  EXPECT_NEAR(rig.az.shaft_deg(), 140.0, 1.0 + 0.44 + 0.5);
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  const auto report = backend->position(rig.t);
  ASSERT_TRUE(report.has_value());
  EXPECT_DOUBLE_EQ(report->el_deg, 0.0);
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
  std::string text = kHardwareStation;
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

}  // namespace
}  // namespace azt::app
