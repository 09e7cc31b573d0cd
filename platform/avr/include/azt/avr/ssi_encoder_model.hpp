#pragma once
// An absolute encoder as its SSI pins see it (docs/encoder-hub.md), for running the hub firmware
// without hardware: the AVR's clock and chip-select edges in, the data line's level out. Pure: time
// is the simulated microseconds the caller passes in.
//
// Generic SSI: the data line idles high; the first falling clock edge after the line has been
// idle latches the count; each rising edge shifts out one bit, MSB first (Gray or binary); after
// the last bit the line is low for the monoflop time, then idle high again. AS5045-class: chip
// select low latches the count and raises the line; rising edges shift out the 18-bit word
// (D11..D0, OCF, COF, LIN, MagINC, MagDEC, even parity); chip select high ends the word.

#include <cstdint>

namespace azt::avr {

enum class EncoderModelKind : std::uint8_t { As5045, SsiBinary, SsiGray };

/// What goes wrong on the encoder's side of the cable.
enum class EncoderFault : std::uint8_t {
  None,
  Stuck,   ///< the data line held low (a short, a dead driver)
  Open,    ///< nothing drives the data line: the receiver's pull-up reads high
  Flip,    ///< one data bit inverted in every other word (a marginal cable)
  Glitch,  ///< every eighth word is noise
};

class SsiEncoderModel {
 public:
  static constexpr double kMonoflopUs = 20.0;

  SsiEncoderModel(EncoderModelKind kind, std::uint8_t bits) : kind_(kind), bits_(bits) {}

  void set_count(std::uint16_t raw) { raw_ = raw; }
  void set_fault(EncoderFault fault) { fault_ = fault; }
  [[nodiscard]] std::uint8_t word_bits() const;

  /// The clock line changed at `now_us`.
  void on_clock(bool high, double now_us);
  /// The chip-select line changed (AS5045-class only).
  void on_chip_select(bool high, double now_us);
  /// The data line's level at `now_us`.
  [[nodiscard]] bool data(double now_us) const;
  /// Words latched so far.
  [[nodiscard]] std::uint32_t words() const { return words_; }

 private:
  void latch();
  [[nodiscard]] bool idle(double now_us) const;
  [[nodiscard]] std::uint32_t word_for(std::uint16_t raw) const;

  EncoderModelKind kind_;
  std::uint8_t bits_;
  std::uint16_t raw_ = 0;
  EncoderFault fault_ = EncoderFault::None;
  std::uint32_t word_ = 0;        ///< the latched word, MSB first in its low word_bits()
  int next_bit_ = -1;             ///< bits shifted out so far; −1 while idle
  bool level_ = true;             ///< what the encoder drives now
  double released_at_us_ = -1e9;  ///< when the last word's monoflop time began
  double last_edge_us_ = -1e9;    ///< the last clock edge
  bool clock_high_ = true;
  std::uint32_t words_ = 0;
  std::uint32_t noise_ = 0x2545F491U;  ///< xorshift state for Glitch
};

}  // namespace azt::avr
