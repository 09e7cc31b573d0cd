#include "rs485_uart.hpp"

#include <avr/interrupt.h>
#include <avr/io.h>

#include "azt/proto/hub_frame.hpp"
#include "board.hpp"

namespace {

uint8_t g_tx_bytes[azt::proto::kHubMaxFrameBytes];
volatile uint8_t g_tx_next = 0;
volatile uint8_t g_tx_size = 0;
volatile bool g_tx_sending = false;

}  // namespace

/// UDR0 is free: the next byte, or, after the last, wait for the shift register to empty.
ISR(USART_UDRE_vect) {
  if (g_tx_next < g_tx_size) {
    UDR0 = g_tx_bytes[g_tx_next];
    g_tx_next = static_cast<uint8_t>(g_tx_next + 1U);
  }
  if (g_tx_next >= g_tx_size) {
    UCSR0B = static_cast<uint8_t>((UCSR0B & ~(1U << UDRIE0)) | (1U << TXCIE0));
  }
}

/// The last stop bit is out: release the bus.
ISR(USART_TX_vect) {
  PORTD = static_cast<uint8_t>(PORTD & ~(1U << azt::hub::board::kDeBit));
  UCSR0B = static_cast<uint8_t>(UCSR0B & ~(1U << TXCIE0));
  g_tx_sending = false;
}

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

bool rs485_sending() { return g_tx_sending; }

void start_rs485(const uint8_t* bytes, size_t size) {
  if (g_tx_sending || size == 0 || size > sizeof g_tx_bytes) return;
  for (size_t i = 0; i < size; ++i) g_tx_bytes[i] = bytes[i];
  g_tx_next = 0;
  g_tx_size = static_cast<uint8_t>(size);
  g_tx_sending = true;
  PORTD = static_cast<uint8_t>(PORTD | (1U << board::kDeBit));
  UCSR0A = static_cast<uint8_t>(UCSR0A | (1U << TXC0));  // writing 1 clears a stale TXC
  UCSR0B = static_cast<uint8_t>(UCSR0B | (1U << UDRIE0));
}

}  // namespace hub
}  // namespace azt
