#pragma once
// The simulated station's EncoderHub as the real firmware (docs/encoder-hub.md, "The firmware in
// the loop"): the plants' encoder counts drive the encoder models on the simulated AVR's pins, and
// the frames its USART sends come back through the daemon's own HubDecoder, each stamped with when
// its last byte left the AVR. The AVR runs alongside the plants in steps of 5 ms.

#include <memory>
#include <optional>
#include <string>

#include "azt/avr/avr_hub.hpp"
#include "azt/avr/ssi_encoder_model.hpp"
#include "azt/sim/plant_setup.hpp"
#include "azt/sim/simulated_hub.hpp"
#include "azt/util/result.hpp"

namespace azt::avr {

class FirmwareHub final : public sim::SimulatedHub {
 public:
  /// Fails naming the ELF when it cannot be loaded. Each axis's encoder is an AS5045-class one
  /// when the plant's encoder has 12 bits, otherwise a generic binary SSI encoder of its bits
  /// (the hub's jumpers set to match).
  static Result<std::unique_ptr<FirmwareHub>> load(const sim::PlantSetup& plant,
                                                   const std::string& elf_path);

  [[nodiscard]] double step_s() const override { return 0.005; }
  void run(const sim::SimAntenna& plants, double step_s) override;
  std::optional<sim::HubArrival> take_frame(const sim::SimAntenna& plants, double now_s) override;
  [[nodiscard]] proto::HubCounters counters() const override { return decoder_.counters(); }
  [[nodiscard]] std::string describe() const override {
    return "simulated antenna read by the EncoderHub firmware on a simulated ATmega328P";
  }

  /// Breaks (or mends) an encoder's cable: tests and rehearsals.
  void set_encoder_fault(bool azimuth, EncoderFault fault) { avr_->set_fault(azimuth, fault); }
  /// The AVR's CPU load so far (avr_hub.hpp).
  [[nodiscard]] double cpu_load() const { return avr_->cpu_load(); }

 private:
  explicit FirmwareHub(std::unique_ptr<AvrHub> avr);

  std::unique_ptr<AvrHub> avr_;
  proto::HubDecoder decoder_{proto::HubAccept::Crc8Only, proto::HubSync::AwaitDelimiter};
  std::optional<proto::HubReading> frame_;
  double frame_at_us_ = -1.0;
  double taken_at_us_ = -1.0;
};

}  // namespace azt::avr
