// The `hardware` backend's brake line and motor inputs (docs/hardware.md "Brake, current and
// temperature"): the brake on a GPIO line, the IBT-2's current sense and an LM35 on the azimuth
// pot's MCP3008, the driver's fault on a GPIO input; simulated devices, virtual time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <string>
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

/// An MCP3008 whose channels read `volts[channel]` (3.3 V reference); counts its transfers.
class SimMcp3008 final : public linux_os::SpiBus {
 public:
  std::function<double(unsigned channel)> volts;
  int transfers = 0;
  Result<bool> transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) override {
    ++transfers;
    if (tx.size() == 3 && rx.size() == 3) {
      const double v = volts((tx[1] >> 4) & 0x7U);
      const auto code = static_cast<unsigned>(std::clamp(std::lround(v / 3.3 * 1024.0), 0L, 1023L));
      rx[0] = 0;
      rx[1] = static_cast<std::uint8_t>((code >> 8) & 0x3U);
      rx[2] = static_cast<std::uint8_t>(code & 0xFFU);
    }
    return true;
  }
};

/// No-op SPI and I²C for the elevation's rotator box and ADS1115 (held where it is).
class Quiet final : public linux_os::SpiBus {
 public:
  Result<bool> transfer(std::span<const std::uint8_t> /*tx*/, std::span<std::uint8_t> rx) override {
    std::fill(rx.begin(), rx.end(), std::uint8_t{0});
    return true;
  }
};
class El final : public linux_os::I2cBus {
 public:
  std::uint8_t pointer = 0;
  Result<bool> write(std::uint8_t /*addr*/, std::span<const std::uint8_t> bytes) override {
    if (!bytes.empty()) pointer = bytes[0];
    return true;
  }
  Result<bool> read(std::uint8_t /*addr*/, std::span<std::uint8_t> bytes) override {
    const std::uint16_t v = pointer == 0x01 ? 0x8000 : 2889;  // ready; 10° of 0..26000 = 90°
    bytes[0] = static_cast<std::uint8_t>(v >> 8);
    bytes[1] = static_cast<std::uint8_t>(v & 0xFFU);
    return true;
  }
};

const std::string kMotorKeys = R"(brake = 13
brake_release_s = 0.8
brake_idle_s = 1.0
current_adc_channel = 1
amps_per_volt = 10.0
current_limit_a = 5.0
current_trip_s = 0.5
temperature_adc_channel = 2
temperature_limit_c = 75.0
driver_fault = 19
)";

std::string station(const std::string& az_keys) {
  std::string text = testing::kHardwareStation;
  const auto el = text.find("[hardware.el]");
  return text.substr(0, el) + az_keys + text.substr(el);
}

struct Rig {
  explicit Rig(const std::string& az_keys = kMotorKeys)
      : config(daemon_config_from(ConfigFile::parse(station(az_keys), "motor.toml"))),
        az(config.sim.az) {
    ports.gpio = &gpio;
    ports.open_spi = [this](const std::string& path,
                            std::uint32_t) -> Result<std::unique_ptr<linux_os::SpiBus>> {
      if (path != "/dev/spidev0.1")
        return std::unique_ptr<linux_os::SpiBus>(std::make_unique<Quiet>());
      auto bus = std::make_unique<SimMcp3008>();
      bus->volts = [this](unsigned ch) {
        if (ch == 1) return amps / 10.0;
        if (ch == 2) return celsius / 100.0;
        return az.shaft_deg() / 450.0 * 3.3;  // the pot
      };
      buses.push_back(bus.get());
      return std::unique_ptr<linux_os::SpiBus>(std::move(bus));
    };
    ports.open_i2c = [](const std::string&) -> Result<std::unique_ptr<linux_os::I2cBus>> {
      return std::unique_ptr<linux_os::I2cBus>(std::make_unique<El>());
    };
  }
  std::unique_ptr<AntennaBackend> open() { return make_hardware_backend(io, config, ports); }
  [[nodiscard]] bool line(const char* key) const {
    const auto it = gpio.outputs.find(key);
    return it != gpio.outputs.end() && it->second;
  }
  /// The azimuth turns with its relays only while its brake's line is on.
  void run(AntennaBackend& a, const control::Demand& demand, double seconds) {
    for (const double end = t + seconds; t < end; t += 0.05) {
      io.restart();  // the fake GPIO's edges arrive through the loop
      io.poll();
      const double duty = line("[hardware.az] relay_forward")   ? 1.0
                          : line("[hardware.az] relay_reverse") ? -1.0
                                                                : 0.0;
      if (duty != 0.0 && !line("[hardware.az] brake")) pulled_against_brake = true;
      az.step(line("[hardware.az] brake") ? duty : 0.0, 0.05);
      a.tick(t, demand, control::AzEl{});
    }
  }
  [[nodiscard]] static bool has(const std::vector<std::string>& faults, const std::string& text) {
    return std::any_of(faults.begin(), faults.end(),
                       [&](const std::string& f) { return f.find(text) != std::string::npos; });
  }

  boost::asio::io_context io;
  DaemonConfig config;
  testing::FakeGpio gpio{io};
  HardwarePorts ports;
  sim::AxisPlant az;
  std::vector<SimMcp3008*> buses;
  double amps = 1.0;
  double celsius = 40.0;
  double t = 0.0;
  bool pulled_against_brake = false;
};

control::Demand go_to(double az_deg) {
  control::Demand d;
  d.position = control::AzEl{az_deg, 10.0};
  return d;
}

TEST(MotorHardware, TheBrakeLineIsOnBeforeTheRelaysCloseAndOffAfterTheIdleTime) {
  Rig rig;
  auto backend = rig.open();
  EXPECT_NE(backend->describe().find("brake on [hardware.az] brake"), std::string::npos)
      << backend->describe();
  rig.run(*backend, go_to(140.0), 0.7);
  EXPECT_TRUE(rig.line("[hardware.az] brake"));
  EXPECT_FALSE(rig.line("[hardware.az] relay_forward")) << "pulled before the brake was off";
  rig.run(*backend, go_to(140.0), 40.0);
  EXPECT_NEAR(rig.az.shaft_deg(), 140.0, 2.5);
  EXPECT_FALSE(rig.pulled_against_brake);
  EXPECT_FALSE(rig.line("[hardware.az] brake")) << "still released long after the move";
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
}

TEST(MotorHardware, ReadingTheMotorAdcTakesTwoTransfersATick) {
  Rig rig;
  auto backend = rig.open();
  ASSERT_EQ(rig.buses.size(), 2U);  // the pot's and the motor's, both on /dev/spidev0.1
  SimMcp3008* motor = rig.buses[1];
  for (int i = 0; i < 20; ++i) {
    const int before = motor->transfers;
    rig.run(*backend, go_to(120.0), 0.05);
    EXPECT_EQ(motor->transfers - before, 2);
  }
}

TEST(MotorHardware, AHotMotorTripsTheAxisUntilItHasCooled) {
  Rig rig;
  auto backend = rig.open();
  rig.run(*backend, go_to(200.0), 3.0);
  ASSERT_TRUE(rig.line("[hardware.az] relay_forward"));
  rig.celsius = 81.0;
  rig.run(*backend, go_to(200.0), 0.1);
  EXPECT_FALSE(rig.line("[hardware.az] relay_forward"));
  EXPECT_FALSE(rig.line("[hardware.az] brake")) << "the brake is applied at once";
  // 0.81 V is code 251 of the MCP3008: 80.9 °C.
  EXPECT_TRUE(Rig::has(backend->faults(), "az: motor_trip: motor temperature 80.9 °C above 75 °C"))
      << backend->faults().front();
  rig.celsius = 72.0;
  rig.run(*backend, go_to(200.0), 0.1);
  backend->clear_faults();
  EXPECT_TRUE(Rig::has(backend->faults(), "az: motor temperature 71.9 °C is not yet below 70 °C"));
  rig.celsius = 60.0;
  rig.run(*backend, go_to(200.0), 0.1);
  backend->clear_faults();
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  rig.run(*backend, go_to(200.0), 2.0);
  EXPECT_TRUE(rig.line("[hardware.az] relay_forward"));
}

TEST(MotorHardware, AStalledMotorsCurrentAndTheDriversFaultLineTrip) {
  Rig rig;
  auto backend = rig.open();
  rig.run(*backend, go_to(200.0), 3.0);
  rig.amps = 12.0;  // a start surge of 0.3 s passes
  rig.run(*backend, go_to(200.0), 0.3);
  rig.amps = 2.0;
  rig.run(*backend, go_to(200.0), 0.2);
  EXPECT_TRUE(backend->faults().empty()) << backend->faults().front();
  rig.amps = 12.0;
  rig.run(*backend, go_to(200.0), 0.6);
  EXPECT_TRUE(Rig::has(backend->faults(), "az: motor_trip: motor current 12.0 A above 5 A"))
      << backend->faults().front();
  EXPECT_FALSE(rig.line("[hardware.az] relay_forward"));
  Rig fault;
  auto b = fault.open();
  fault.run(*b, go_to(200.0), 1.0);
  fault.gpio.set_input("[hardware.az] driver_fault", true);
  fault.run(*b, go_to(200.0), 0.1);
  EXPECT_TRUE(Rig::has(b->faults(), "az: motor_trip: motor driver reports a fault"));
}

TEST(MotorHardware, MotorKeysWithoutTheirPartnersAreRefusedNamingTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"current_adc_channel = 1\n", "current_limit_a is needed"},
      {"temperature_limit_c = 70.0\n", "temperature_limit_c needs temperature_adc_channel"},
      {"current_adc_channel = 0\ncurrent_limit_a = 4.0\n", "current_adc_channel is the pot's"},
      {"brake = 5\n", "is the same line as"},
  };
  for (const auto& [keys, words] : cases) {
    try {
      Rig rig(keys);
      FAIL() << "accepted " << keys;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace azt::app
