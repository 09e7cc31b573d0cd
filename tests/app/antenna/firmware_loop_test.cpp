// The firmware in the loop (docs/encoder-hub.md): the one station backend drives the simulated
// plants, reading them through the real EncoderHub ELF on a simulated ATmega328P and the daemon's
// own frame decoder, in virtual time (the AVR's cycles run for exactly the time each tick asks).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "antenna/station_backend.hpp"
#include "azt/avr/firmware_hub.hpp"
#include "azt/sim/reference_station.hpp"
#include "azt/sim/simulated_station.hpp"

namespace azt::app {
namespace {

struct Loop {
  sim::StationSimSetup setup = sim::reference_station(12, 0.1);
  avr::FirmwareHub* firmware = nullptr;  ///< owned by the rig
  std::shared_ptr<const sim::PlantRig> rig;
  std::unique_ptr<AntennaBackend> backend;
  double t = 0.0;

  explicit Loop(bool use_firmware) {
    std::unique_ptr<sim::SimulatedHub> hub;
    if (use_firmware) {
      auto loaded = avr::FirmwareHub::load(setup.plant, AZT_HUB_ELF);
      EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message);
      firmware = loaded.value().get();
      hub = std::move(loaded).value();
    } else {
      hub = sim::make_model_hub(setup.plant);
    }
    auto station = sim::make_simulated_station(setup.plant, std::move(hub));
    rig = station.rig;
    backend =
        make_station_backend(sim::station_control_config(setup),
                             control::AzEl{setup.plant.az.start_deg, setup.plant.el.start_deg},
                             setup.station.corrections, std::move(station.ports), "loop");
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
// and both drives are off within 200 ms of the last good frame (R01).
TEST(FirmwareLoop, ADisconnectedEncoderMidSlewStopsTheDriveWithin200ms) {
  Loop loop(true);
  const control::Demand go = slew_to(loop.setup);
  loop.run(go, 3.0);
  ASSERT_TRUE(loop.backend->position(loop.t).has_value());
  ASSERT_NE(loop.rig->duty(0), 0.0) << "the azimuth drive should be slewing";
  const double cut_s = loop.t;
  loop.firmware->set_encoder_fault(true, avr::EncoderFault::Open);
  double unknown_s = -1.0;
  double off_s = -1.0;
  while (loop.t < cut_s + 1.0) {
    loop.backend->tick(loop.t, go, control::AzEl{});
    if (!loop.backend->position(loop.t) && unknown_s < 0) unknown_s = loop.t;
    const bool drives_off = loop.rig->duty(0) == 0.0 && loop.rig->duty(1) == 0.0;
    if (drives_off && off_s < 0) off_s = loop.t;
    if (!drives_off) off_s = -1.0;  // off for good, not between two pulses
    loop.t += loop.setup.station.tick_s;
  }
  ASSERT_GE(unknown_s, 0.0) << "the station kept a position with its encoder cut";
  ASSERT_GE(off_s, 0.0) << "a drive still runs with its encoder cut";
  // The last good frame was read at most one frame period (20 ms) before the cut.
  EXPECT_LE(unknown_s - cut_s, 0.2 + 0.02);
  EXPECT_LE(off_s - cut_s, 0.2 + 0.02);
  std::printf("[ measure  ] encoder cut: position gone after %.0f ms, drives off after %.0f ms\n",
              1000.0 * (unknown_s - cut_s), 1000.0 * (off_s - cut_s));
  const auto faults = loop.backend->faults();
  bool named = false;
  for (const auto& f : faults) named = named || f == "az encoder (EncoderHub): no encoder answers";
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace azt::app
