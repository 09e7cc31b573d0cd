// The firmware in the loop (issue 14 §2, §3): the one station backend drives the simulated
// plants, reading them through the real EncoderHub ELF on a simulated ATmega328P and the daemon's
// own frame decoder, in virtual time (the AVR's cycles run for exactly the time each tick asks).
#include <gtest/gtest.h>

#include <cmath>

#include "antenna/station_backend.hpp"
#include "azt/avr/firmware_station_ports.hpp"
#include "azt/sim/reference_station.hpp"
#include "azt/sim/sim_station_ports.hpp"

namespace azt::app {
namespace {

struct Loop {
  sim::StationSimSetup setup = sim::reference_station(12, 0.1);
  std::function<void(bool, avr::EncoderFault)> break_encoder;
  std::unique_ptr<AntennaBackend> backend;
  double t = 0.0;

  explicit Loop(bool firmware) {
    ports::StationPorts p;
    if (firmware) {
      auto station = avr::make_firmware_station(setup.plant, AZT_HUB_ELF);
      EXPECT_TRUE(station.ok()) << (station.ok() ? "" : station.error().message);
      p = std::move(station.value().ports);
      break_encoder = station.value().set_encoder_fault;
    } else {
      p = sim::make_sim_station_ports(setup.plant);
    }
    backend =
        make_station_backend(sim::station_control_config(setup),
                             control::AzEl{setup.plant.az.start_deg, setup.plant.el.start_deg},
                             setup.station.corrections, std::move(p), "loop");
  }

  void run(const control::Demand& demand, double seconds) {
    for (const double end = t + seconds; t < end; t += setup.station.tick_s) {
      backend->tick(t, demand, control::AzEl{});
    }
  }
};

control::Demand slew_to(const sim::StationSimSetup& s) {
  control::Demand d;
  d.position = control::AzEl{s.plant.az.start_deg + 20.0, s.plant.el.start_deg + 15.0};
  return d;
}

// The same slew, read through the firmware and through the plain model, ends in the same window.
TEST(FirmwareLoop, ASlewEndsWithinTheWindowAsThePlainSimulationDoes) {
  for (bool firmware : {false, true}) {
    Loop loop(firmware);
    const control::Demand go = slew_to(loop.setup);
    loop.run(go, 25.0);
    const auto here = loop.backend->position(loop.t);
    ASSERT_TRUE(here.has_value()) << firmware;
    const double lsb = 360.0 / 4096.0;
    EXPECT_NEAR(here->az_deg, go.position->az_deg, 0.1 + lsb) << "firmware " << firmware;
    EXPECT_NEAR(here->el_deg, go.position->el_deg, 0.1 + lsb) << "firmware " << firmware;
    EXPECT_TRUE(loop.backend->faults().empty()) << loop.backend->faults().front();
  }
}

// A cable cut mid-slew: the hub says "no encoder answers", no false angle reaches the station,
// and the drive is off within 200 ms of the last good frame (R01).
TEST(FirmwareLoop, ADisconnectedEncoderMidSlewStopsTheDriveWithin200ms) {
  Loop loop(true);
  const control::Demand go = slew_to(loop.setup);
  loop.run(go, 3.0);
  ASSERT_TRUE(loop.backend->position(loop.t).has_value());
  const double cut_s = loop.t;
  loop.break_encoder(true, avr::EncoderFault::Open);
  double off_s = -1.0;
  while (loop.t < cut_s + 1.0) {
    loop.backend->tick(loop.t, go, control::AzEl{});
    const auto here = loop.backend->position(loop.t);
    if (!here && off_s < 0) off_s = loop.t;
    loop.t += loop.setup.station.tick_s;
  }
  ASSERT_GE(off_s, 0.0) << "the station kept a position with its encoder cut";
  // The last good frame was read at most one frame period (20 ms) before the cut.
  EXPECT_LE(off_s - cut_s, 0.2 + 0.02);
  const auto faults = loop.backend->faults();
  bool named = false;
  for (const auto& f : faults) named = named || f == "az encoder (EncoderHub): no encoder answers";
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace azt::app
