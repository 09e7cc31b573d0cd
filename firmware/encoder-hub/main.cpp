// The EncoderHub firmware (docs/encoder-hub.md): reads two absolute encoders and sends both counts
// to the controller over RS-485, 50 times a second, in the CRC-8 frame version of
// azt/proto/hub_frame.hpp (the daemon's own decoder header). ATmega328P at 16 MHz, no Arduino
// core: registers, Timer1 for the frame period, the watchdog for a hung loop. Between frames,
// and while a frame is on the wire, the CPU sleeps (idle mode: the timer and USART run on).
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/wdt.h>
#include <util/delay.h>

#include "azt/proto/hub_frame.hpp"
#include "board.hpp"
#include "hub_reading.hpp"
#include "jumpers.hpp"
#include "reading_agreement.hpp"
#include "rs485_uart.hpp"
#include "ssi_bus.hpp"

namespace {

using azt::hub::AxisJumpers;
using azt::hub::HubJumpers;
using azt::hub::SsiCount;

constexpr uint16_t kFramePeriodTicks = 5000;  ///< 20 ms at 16 MHz / 64: 50 frames a second
constexpr uint16_t kAgreeCounts = 4;          ///< the two reads of one frame, at most this apart
constexpr uint8_t kLedToggleFrames = 5;       ///< 100 ms on, 100 ms off while in error

const azt::hub::board::SsiPins kAzPins{&PORTD, PD3, &PIND, PD4, &PORTD, PD5};
const azt::hub::board::SsiPins kElPins{&PORTD, PD6, &PIND, PD7, &PORTB, PB0};

/// A6 / A7 (BAUD0 / BAUD1) below half the supply: the jumper to GND is fitted.
bool analog_jumper(uint8_t channel) {
  ADMUX = static_cast<uint8_t>((1U << REFS0) | channel);            // AVcc reference
  ADCSRA = static_cast<uint8_t>((1U << ADEN) | (1U << ADSC) | 7U);  // 125 kHz ADC clock
  while ((ADCSRA & (1U << ADSC)) != 0) {
  }
  const uint16_t code = ADC;
  ADCSRA = 0;
  return code < 512U;
}

/// The jumpers as the `fitted` word of jumpers.hpp: digital pins with pull-ups, fitted = low.
uint16_t fitted_jumpers() {
  PORTB = static_cast<uint8_t>(PORTB | 0x1EU);  // PB1..PB4 pull-ups
  PORTC = static_cast<uint8_t>(PORTC | 0x3FU);  // PC0..PC5 pull-ups
  _delay_ms(1);
  const uint8_t pinb = static_cast<uint8_t>(~PINB);
  const uint8_t pinc = static_cast<uint8_t>(~PINC);
  uint16_t fitted = static_cast<uint16_t>((pinb >> 1U) & 0x0FU);            // az RES0..RES2, TYPE0
  fitted = static_cast<uint16_t>(fitted | ((pinc & 0x01U) << 4U));          // az TYPE1
  fitted = static_cast<uint16_t>(fitted | (((pinc >> 1U) & 0x1FU) << 5U));  // el five
  if (analog_jumper(6)) fitted = static_cast<uint16_t>(fitted | (1U << azt::hub::kJumperBaud0));
  if (analog_jumper(7)) fitted = static_cast<uint16_t>(fitted | (1U << azt::hub::kJumperBaud1));
  return fitted;
}

/// Two reads of one axis, agreed or not.
SsiCount read_twice(const azt::hub::board::SsiPins& pins, const AxisJumpers& j) {
  if (j.kind == azt::hub::EncoderKind::Unknown)
    return SsiCount{0, azt::proto::HubAxisError::BadJumpers};
  const SsiCount first = azt::hub::read_axis(pins, j);
  const SsiCount second = azt::hub::read_axis(pins, j);
  return azt::hub::agreed_count(first, second, j.bits, kAgreeCounts);
}

volatile bool g_frame_due = false;

/// Sleeps until an interrupt has made `done()` true. Interrupts are off between the test and
/// the sleep instruction (sei takes effect after the next one), so no wake-up is missed.
template <typename Done>
void sleep_until(Done done) {
  cli();
  while (!done()) {
    sleep_enable();
    sei();
    sleep_cpu();
    sleep_disable();
    cli();
  }
  sei();
}

void wait_for_frame_time() {
  sleep_until([] { return g_frame_due; });
  g_frame_due = false;
}

void start_frame_timer() {
  TCCR1A = 0;
  TCCR1B = static_cast<uint8_t>((1U << WGM12) | (1U << CS11) | (1U << CS10));  // CTC, /64
  OCR1A = kFramePeriodTicks - 1U;
  TIMSK1 = static_cast<uint8_t>(1U << OCIE1A);
}

}  // namespace

ISR(TIMER1_COMPA_vect) { g_frame_due = true; }

int main() {
  // A watchdog reset leaves the watchdog running at its shortest period: stop it first.
  MCUSR = 0;
  wdt_disable();
  const HubJumpers jumpers = azt::hub::read_jumpers(fitted_jumpers());
  azt::hub::init_ssi(kAzPins);
  azt::hub::init_ssi(kElPins);
  azt::hub::init_rs485(jumpers.baud);
  DDRB = static_cast<uint8_t>(DDRB | (1U << azt::hub::board::kLedBit));
  start_frame_timer();
  // set_sleep_mode() trips -Wconversion in avr-libc's macro: the same, written out.
  SMCR = static_cast<uint8_t>(SMCR & ~((1U << SM0) | (1U << SM1) | (1U << SM2)));  // idle
  sei();
  // 120 ms nominal (the watchdog oscillator may run slow at low voltage): a loop that stops
  // sending is reset well inside 250 ms.
  wdt_enable(WDTO_120MS);
  uint8_t frame[azt::proto::kHubMaxFrameBytes];
  uint8_t in_error = 0;
  for (;;) {
    wait_for_frame_time();
    wdt_reset();
    const azt::proto::HubReading r = azt::hub::hub_reading(jumpers, read_twice(kAzPins, jumpers.az),
                                                           read_twice(kElPins, jumpers.el));
    const size_t n =
        azt::proto::encode_hub_frame(r, azt::proto::HubFrameVersion::Crc8, frame, sizeof frame);
    // At 9600 baud a frame takes 8 ms on the wire: the last one has long gone, but wait anyway.
    sleep_until([] { return !azt::hub::rs485_sending(); });
    if (n != 0) azt::hub::start_rs485(frame, n);
    // The LED blinks while any axis reports an error, and is off otherwise.
    if (azt::proto::hub_reading_has_error(r)) {
      if (++in_error >= kLedToggleFrames) {
        in_error = 0;
        PINB = static_cast<uint8_t>(1U << azt::hub::board::kLedBit);  // writing PINx toggles
      }
    } else {
      in_error = 0;
      PORTB = static_cast<uint8_t>(PORTB & ~(1U << azt::hub::board::kLedBit));
    }
  }
}
