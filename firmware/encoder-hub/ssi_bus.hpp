#pragma once
// Bit-banged SSI on the AVR (docs/encoder-hub.md): the clock idles high; each clock is a low half
// then a high half of about 2 µs (≈ 250 kHz, well inside the AS5045's 1 MHz and a generic encoder's
// limits on a short cable), the data bit sampled after the rising edge that shifts it out.

#include <stdint.h>

#include "board.hpp"
#include "jumpers.hpp"
#include "ssi_reading.hpp"

namespace azt {
namespace hub {

/// One read of one axis: the word and the two line checks, decoded as its jumpers say.
SsiCount read_axis(const board::SsiPins& pins, const AxisJumpers& jumpers);

/// Clock outputs high, chip-selects high (AS5045 idle), data inputs without pull-up (the line
/// is the encoder's; an RS-422 receiver drives it).
void init_ssi(const board::SsiPins& pins);

}  // namespace hub
}  // namespace azt
