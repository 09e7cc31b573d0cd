#pragma once
// The simulated antenna read through the real hub firmware (issue 14 §2, "firmware in the
// loop"): the plants' shaft angles drive the encoder models on the simulated AVR's pins, and the
// frames its USART sends come back through the daemon's own HubDecoder. The drives set the
// plants' duties; the first sensor read at a new time runs the plants and the AVR, in steps of
// 5 ms, for the time since the last read (capped at 1 s), then both axes report the newest
// frame, stamped with when its last byte left the AVR.

#include <functional>
#include <string>

#include "azt/avr/ssi_encoder_model.hpp"
#include "azt/ports/station_ports.hpp"
#include "azt/sim/station_sim.hpp"
#include "azt/util/result.hpp"

namespace azt::avr {

/// The ports, and a way to break an encoder's cable (tests, rehearsals).
struct FirmwareStation {
  ports::StationPorts ports;
  std::function<void(bool azimuth, EncoderFault fault)> set_encoder_fault;
};

/// Fails naming the ELF when it cannot be loaded. Each axis's encoder is an AS5045-class one
/// when the plant's encoder has 12 bits, otherwise a generic binary SSI encoder of its bits (the
/// hub's jumpers set to match).
Result<FirmwareStation> make_firmware_station(const sim::PlantSetup& plant,
                                              const std::string& elf_path);

}  // namespace azt::avr
