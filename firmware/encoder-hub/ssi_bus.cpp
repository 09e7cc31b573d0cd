#include "ssi_bus.hpp"

#include <util/delay.h>

namespace azt {
namespace hub {
namespace {

constexpr double kHalfClockUs = 1.0;
constexpr double kCsSetupUs = 1.0;    ///< AS5045 t_CLKFE: 500 ns from CSn low to first edge
constexpr double kMonoflopUs = 25.0;  ///< SSI tm: the line is released before the next read

inline void set(volatile uint8_t* port, uint8_t bit, bool high) {
  if (high) {
    *port = static_cast<uint8_t>(*port | (1U << bit));
  } else {
    *port = static_cast<uint8_t>(*port & ~(1U << bit));
  }
}

inline bool data(const board::SsiPins& p) { return ((*p.data_pin >> p.data_bit) & 1U) != 0; }

/// One clock: low, high, then the bit the rising edge shifted out.
inline bool clock_bit(const board::SsiPins& p) {
  set(p.clk_port, p.clk_bit, false);
  _delay_us(kHalfClockUs);
  set(p.clk_port, p.clk_bit, true);
  _delay_us(kHalfClockUs);
  return data(p);
}

}  // namespace

void init_ssi(const board::SsiPins& p) {
  set(p.clk_port, p.clk_bit, true);
  set(p.cs_port, p.cs_bit, true);
  // DDR is the register below PORT on the ATmega328P (PINx, DDRx, PORTx).
  set(p.clk_port - 1, p.clk_bit, true);
  set(p.cs_port - 1, p.cs_bit, true);
  set(p.data_pin + 1, p.data_bit, false);
  set(p.data_pin + 2, p.data_bit, false);
}

SsiCount read_axis(const board::SsiPins& p, const AxisJumpers& jumpers) {
  const bool as5045 = jumpers.kind == EncoderKind::As5045;
  if (as5045) {
    set(p.cs_port, p.cs_bit, false);
    _delay_us(kCsSetupUs);
  }
  const bool idle_high = data(p);
  uint32_t word = 0;
  const uint8_t n = word_bits(jumpers);
  for (uint8_t i = 0; i < n; ++i) word = (word << 1U) | (clock_bit(p) ? 1UL : 0UL);
  // Generic SSI: one more clock must find the line low (the monoflop time after the word).
  const bool trailer_low = as5045 ? true : !clock_bit(p);
  if (as5045) set(p.cs_port, p.cs_bit, true);
  _delay_us(kMonoflopUs);
  if (as5045) return decode_as5045(word, idle_high, trailer_low);
  return decode_generic_ssi(word, jumpers.bits, jumpers.code, idle_high, trailer_low);
}

}  // namespace hub
}  // namespace azt
