#pragma once
// USART0 to a MAX485 (issue 14 §1): 8N1 at the jumpers' baud rate, transmit only. DE (with /RE)
// goes high just before the first byte and low once the last stop bit has left the shift
// register (TXC), never after the last byte was merely handed to UDR0: dropping DE there would
// cut the last byte on the cable.

#include <stddef.h>
#include <stdint.h>

namespace azt {
namespace hub {

/// U2X mode (8 samples a bit) for the smallest rate error at 16 MHz: 0.2 % at 9600 and 38400,
/// 2.1 % at 115200.
void init_rs485(uint32_t baud);

/// Sends `size` bytes and returns once the line is released (DE low). Polls: nothing else has
/// to run meanwhile, and the watchdog covers a USART that never finishes.
void send_rs485(const uint8_t* bytes, size_t size);

}  // namespace hub
}  // namespace azt
