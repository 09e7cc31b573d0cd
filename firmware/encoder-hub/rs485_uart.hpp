#pragma once
// USART0 to a MAX485 (docs/encoder-hub.md): 8N1 at the jumpers' baud rate, transmit only, driven by
// interrupts so that the CPU sleeps while a frame is on the wire. DE (with /RE) goes high just
// before the first byte and low once the last stop bit has left the shift register (the TXC
// interrupt), never after the last byte was merely handed to UDR0: dropping DE there would cut
// the last byte on the cable.

#include <stddef.h>
#include <stdint.h>

namespace azt {
namespace hub {

/// U2X mode (8 samples a bit) for the smallest rate error at 16 MHz: 0.2 % at 9600 and 38400,
/// 2.1 % at 115200.
void init_rs485(uint32_t baud);

/// True from start_rs485 until the driver is released after the last stop bit.
bool rs485_sending();

/// Copies up to kHubMaxFrameBytes bytes, raises DE and starts sending; returns at once. Ignored
/// while a frame is still being sent (the caller waits for rs485_sending() to clear).
void start_rs485(const uint8_t* bytes, size_t size);

}  // namespace hub
}  // namespace azt
