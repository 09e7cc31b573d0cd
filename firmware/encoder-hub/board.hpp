#pragma once
// The hub's pins on an Arduino Nano (ATmega328P, 16 MHz): docs/encoder-hub.md draws the wiring.
//   D1  PD1  TXD   -> MAX485 DI            D2  PD2  -> MAX485 DE and /RE (high only to send)
//   D13 PB5  LED   (blinks while an axis has an error)
//   D3  PD3  az CLK    D4 PD4 az DATA    D5 PD5 az CSn (AS5045)
//   D6  PD6  el CLK    D7 PD7 el DATA    D8 PB0 el CSn (AS5045)
//   az jumpers: D9 PB1 RES0, D10 PB2 RES1, D11 PB3 RES2, D12 PB4 TYPE0, A0 PC0 TYPE1
//   el jumpers: A1 PC1 RES0, A2 PC2 RES1, A3 PC3 RES2, A4 PC4 TYPE0, A5 PC5 TYPE1
//   A6 BAUD0, A7 BAUD1: analog-only pins, read by the ADC; each needs a 10 kΩ pull-up to 5 V
// A fitted jumper connects its pin to GND; the digital ones have the AVR's own pull-ups.

#include <avr/io.h>
#include <stdint.h>

namespace azt {
namespace hub {
namespace board {

constexpr uint8_t kDeBit = PD2;
constexpr uint8_t kLedBit = PB5;

/// One axis's SSI pins: clock and chip-select are outputs, data an input.
struct SsiPins {
  volatile uint8_t* clk_port;
  uint8_t clk_bit;
  volatile uint8_t* data_pin;
  uint8_t data_bit;
  volatile uint8_t* cs_port;
  uint8_t cs_bit;
};

}  // namespace board
}  // namespace hub
}  // namespace azt
