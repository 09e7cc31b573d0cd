#pragma once
// The EncoderHub firmware running on a simulated ATmega328P (simavr, docs/encoder-hub.md): the real
// ELF, its jumper pins set as a station would fit them, an encoder model on each axis's SSI pins
// and the bytes its USART sends, each with its simulated time. Time is the AVR's own: 16 MHz
// cycles, so byte timing and frame rate are measured, not assumed.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "azt/avr/ssi_encoder_model.hpp"
#include "azt/util/result.hpp"

namespace azt::avr {

struct HubAxisSetup {
  EncoderModelKind kind = EncoderModelKind::As5045;
  std::uint8_t bits = 12;  ///< generic SSI: 9..16; AS5045-class: 12
};

struct AvrHubSetup {
  std::string elf_path;
  HubAxisSetup az;
  HubAxisSetup el;
  std::uint32_t baud = 38400;  ///< 9600, 38400 or 115200: set by the BAUD jumpers
};

class AvrHub {
 public:
  /// Fails naming the file when the ELF cannot be read or is not for an ATmega328P.
  static Result<std::unique_ptr<AvrHub>> load(const AvrHubSetup& setup);
  ~AvrHub();
  AvrHub(const AvrHub&) = delete;
  AvrHub& operator=(const AvrHub&) = delete;
  AvrHub(AvrHub&&) = delete;
  AvrHub& operator=(AvrHub&&) = delete;

  /// The counts the encoders report from now on (the shafts' angles).
  void set_counts(std::uint16_t az_raw, std::uint16_t el_raw);
  void set_fault(bool azimuth, EncoderFault fault);

  /// Every byte the USART sends, with the simulated time it was sent (µs since power-up).
  std::function<void(std::uint8_t byte, double at_us)> on_byte;
  /// Every change of the RS-485 driver enable (DE, high = sending), with its simulated time.
  std::function<void(bool high, double at_us)> on_driver;

  /// Runs the firmware until `seconds` more of simulated time have passed.
  void run_for(double seconds);
  [[nodiscard]] double now_us() const;

  /// Freezes the firmware where it is (its next instruction jumps to itself), as a hung loop
  /// would, until the watchdog resets it; the code is whole again after the reset.
  void hang();
  /// Watchdog resets so far.
  [[nodiscard]] std::uint32_t resets() const;
  /// The CPU's load: the share of cycles it was awake (not in its sleep instruction), counted
  /// from the first time the firmware slept.
  [[nodiscard]] double cpu_load() const;

 private:
  struct Impl;
  void run_until(std::uint64_t end_cycle);
  explicit AvrHub(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace azt::avr
