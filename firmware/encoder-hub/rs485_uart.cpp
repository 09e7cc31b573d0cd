#include "rs485_uart.hpp"

#include <avr/io.h>

#include "board.hpp"

namespace azt {
namespace hub {

void init_rs485(uint32_t baud) {
  PORTD = static_cast<uint8_t>(PORTD & ~(1U << board::kDeBit));  // receive (released) at start
  DDRD = static_cast<uint8_t>(DDRD | (1U << board::kDeBit));
  const uint16_t ubrr = static_cast<uint16_t>((F_CPU / 8UL + baud / 2UL) / baud - 1UL);
  UBRR0H = static_cast<uint8_t>(ubrr >> 8U);
  UBRR0L = static_cast<uint8_t>(ubrr & 0xFFU);
  UCSR0A = static_cast<uint8_t>(1U << U2X0);
  UCSR0C = static_cast<uint8_t>((1U << UCSZ01) | (1U << UCSZ00));  // 8N1
  UCSR0B = static_cast<uint8_t>(1U << TXEN0);
}

void send_rs485(const uint8_t* bytes, size_t size) {
  PORTD = static_cast<uint8_t>(PORTD | (1U << board::kDeBit));
  UCSR0A = static_cast<uint8_t>(UCSR0A | (1U << TXC0));  // writing 1 clears a stale TXC
  for (size_t i = 0; i < size; ++i) {
    while ((UCSR0A & (1U << UDRE0)) == 0) {
    }
    UDR0 = bytes[i];
  }
  while ((UCSR0A & (1U << TXC0)) == 0) {
  }
  PORTD = static_cast<uint8_t>(PORTD & ~(1U << board::kDeBit));
}

}  // namespace hub
}  // namespace azt
