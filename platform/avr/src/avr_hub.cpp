#include "azt/avr/avr_hub.hpp"

#include <simavr/avr_adc.h>
#include <simavr/avr_extint.h>
#include <simavr/avr_ioport.h>
#include <simavr/avr_uart.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <optional>
#include <utility>

namespace azt::avr {
namespace {

constexpr double kCpuHz = 16e6;

/// A pin of the simulated chip: its port letter and bit (docs/encoder-hub.md has the map).
struct Pin {
  char port;
  int bit;
};

struct AxisPins {
  Pin clk, data, cs;
};

constexpr AxisPins kAzPins{{'D', 3}, {'D', 4}, {'D', 5}};
constexpr AxisPins kElPins{{'D', 6}, {'D', 7}, {'B', 0}};
constexpr Pin kDePin{'D', 2};
/// RES0, RES1, RES2, TYPE0, TYPE1 of each axis.
constexpr std::array<Pin, 5> kAzJumpers{{{'B', 1}, {'B', 2}, {'B', 3}, {'B', 4}, {'C', 0}}};
constexpr std::array<Pin, 5> kElJumpers{{{'C', 1}, {'C', 2}, {'C', 3}, {'C', 4}, {'C', 5}}};

/// simavr's own messages ("Loaded 2298 bytes of Flash data") go to stderr, never among the
/// USART's bytes on stdout, and only its warnings and errors.
void quiet_logger(avr_t* /*avr*/, const int level, const char* format, va_list ap) {
  if (level > LOG_WARNING) return;
  std::vfprintf(stderr, format, ap);  // NOLINT(cert-err33-c): a log line, nothing to recover
}

/// The five jumpers of an axis as fitted (bit set = fitted), as jumpers.hpp reads them.
unsigned fitted_for(const HubAxisSetup& a) {
  if (a.kind == EncoderModelKind::As5045) return 0;
  const unsigned res = static_cast<unsigned>(a.bits - 9) & 7U;
  return res | (a.kind == EncoderModelKind::SsiBinary ? 1U << 3U : 1U << 4U);
}

}  // namespace

struct AvrHub::Impl {
  avr_t* avr = nullptr;
  elf_firmware_t firmware{};
  std::array<SsiEncoderModel, 2> encoders;
  std::array<avr_irq_t*, 2> data_irq{};
  AvrHub* owner = nullptr;
  std::uint32_t resets = 0;
  std::optional<std::pair<avr_flashaddr_t, std::array<std::uint8_t, 2>>> patched;
  // the CPU's load: cycles spent asleep since its first sleep (the setup before it is not the
  // steady state)
  avr_cycle_count_t asleep_cycles = 0;
  double until_cycle = 0.0;  ///< where run_for has been asked to run to, in cycles
  avr_cycle_count_t load_since_cycle = 0;
  bool load_started = false;

  unsigned az_fitted = 0;  ///< the axes' five jumpers, bit set = fitted (jumpers.hpp)
  unsigned el_fitted = 0;

  Impl(const HubAxisSetup& az, const HubAxisSetup& el)
      : encoders{SsiEncoderModel(az.kind, az.bits), SsiEncoderModel(el.kind, el.bits)},
        az_fitted(fitted_for(az)),
        el_fitted(fitted_for(el)) {}

  /// Sets an input pin's level even if simavr believes it is there already: its IRQ passes
  /// on changes only, and a reset clears the pin register but not the IRQ's last value.
  static void force(avr_irq_t* irq, std::uint32_t level) {
    avr_raise_irq(irq, level ^ 1U);
    avr_raise_irq(irq, level);
  }

  /// A fitted jumper holds its pin low, an open one reads high (the AVR's pull-up).
  void drive_jumpers() {
    for (std::size_t i = 0; i < 5; ++i) {
      force(pin_irq(kAzJumpers.at(i)), ((az_fitted >> i) & 1U) != 0 ? 0U : 1U);
      force(pin_irq(kElJumpers.at(i)), ((el_fitted >> i) & 1U) != 0 ? 0U : 1U);
    }
  }

  static avr_cycle_count_t redrive_jumpers(avr_t* /*avr*/, avr_cycle_count_t /*when*/,
                                           void* param) {
    static_cast<Impl*>(param)->drive_jumpers();
    return 0;
  }

  /// The firmware writing PORTB/PORTC (its pull-ups) makes simavr drive those pins from the
  /// register; the jumpers are wires, so they take their pins back a moment later, long before
  /// the firmware reads them (it waits 1 ms).
  static void port_written(avr_irq_t* /*irq*/, std::uint32_t /*value*/, void* param) {
    auto* self = static_cast<Impl*>(param);
    avr_cycle_timer_register_usec(self->avr, 5, &Impl::redrive_jumpers, self);
  }

  /// simavr polls INT0 / INT1 at every cycle while their pins (DE and the azimuth clock) are
  /// low, as a level-triggered interrupt would need, even with the interrupts disabled: a
  /// sleeping hub then costs as much as a busy one. The firmware enables neither, so the poll
  /// is switched off; each reset switches it on again.
  void stop_level_polling() {
    avr_extint_set_strict_lvl_trig(avr, 0, 0);
    avr_extint_set_strict_lvl_trig(avr, 1, 0);
  }

  [[nodiscard]] double now_us() const { return static_cast<double>(avr->cycle) / kCpuHz * 1e6; }

  avr_irq_t* pin_irq(Pin p) const {
    return avr_io_getirq(avr, static_cast<std::uint32_t>(AVR_IOCTL_IOPORT_GETIRQ(p.port)), p.bit);
  }

  void drive_data(std::size_t axis) {
    avr_raise_irq(data_irq.at(axis), encoders.at(axis).data(now_us()) ? 1U : 0U);
  }

  /// The data line also changes with time alone (the monoflop time ends): look again then.
  static avr_cycle_count_t recheck(avr_t* /*avr*/, avr_cycle_count_t /*when*/, void* param) {
    auto* self = static_cast<Impl*>(param);
    self->drive_data(0);
    self->drive_data(1);
    return 0;
  }

  void on_edge(std::size_t axis, bool clock, bool high) {
    const double t = now_us();
    if (clock) {
      encoders.at(axis).on_clock(high, t);
    } else {
      encoders.at(axis).on_chip_select(high, t);
    }
    drive_data(axis);
    avr_cycle_timer_register_usec(avr, static_cast<std::uint32_t>(SsiEncoderModel::kMonoflopUs + 1),
                                  &Impl::recheck, this);
  }

  template <std::size_t Axis, bool Clock>
  static void edge_hook(avr_irq_t* /*irq*/, std::uint32_t value, void* param) {
    static_cast<Impl*>(param)->on_edge(Axis, Clock, value != 0);
  }

  /// A cycle timer that only ends a sleep (run_for's end).
  static avr_cycle_count_t wake_at_end(avr_t* /*avr*/, avr_cycle_count_t /*when*/,
                                       void* /*param*/) {
    return 0;
  }

  /// simavr's sleep hook: it skips the cycles itself (and would wait as long in wall time).
  static void on_sleep(avr_t* avr, avr_cycle_count_t how_long) {
    auto* self = static_cast<Impl*>(avr->custom.data);
    if (!self->load_started) {
      self->load_started = true;
      self->load_since_cycle = avr->cycle;
    }
    self->asleep_cycles += 1 + how_long;
  }

  static void driver_hook(avr_irq_t* /*irq*/, std::uint32_t value, void* param) {
    auto* self = static_cast<Impl*>(param);
    if (self->owner->on_driver) self->owner->on_driver(value != 0, self->now_us());
  }

  static void uart_hook(avr_irq_t* /*irq*/, std::uint32_t value, void* param) {
    auto* self = static_cast<Impl*>(param);
    if (self->owner->on_byte)
      self->owner->on_byte(static_cast<std::uint8_t>(value), self->now_us());
  }
};

Result<std::unique_ptr<AvrHub>> AvrHub::load(const AvrHubSetup& setup) {
  avr_global_logger_set(quiet_logger);
  auto impl = std::make_unique<Impl>(setup.az, setup.el);
  if (elf_read_firmware(setup.elf_path.c_str(), &impl->firmware) != 0) {
    return fail(setup.elf_path + ": not a readable AVR ELF file");
  }
  impl->firmware.frequency = static_cast<std::uint32_t>(kCpuHz);
  std::strncpy(impl->firmware.mmcu, "atmega328p", sizeof impl->firmware.mmcu - 1);
  impl->avr = avr_make_mcu_by_name("atmega328p");
  if (impl->avr == nullptr) return fail("simavr has no ATmega328P");
  avr_init(impl->avr);
  avr_load_firmware(impl->avr, &impl->firmware);
  impl->avr->log = 0;
  impl->stop_level_polling();
  // A sleeping AVR is paced to the wall clock by simavr; our time is its own cycles, so a sleep
  // costs no wall time, and is counted for the load.
  impl->avr->custom.data = impl.get();
  impl->avr->sleep = &Impl::on_sleep;
  // The board's supply: 5 V, and AVcc (the ADC's reference for the BAUD jumpers) with it.
  impl->avr->vcc = 5000;
  impl->avr->avcc = 5000;
  impl->avr->aref = 5000;
  Impl* raw = impl.get();
  // The USART's bytes come to us, not to simavr's console.
  std::uint32_t flags = 0;
  avr_ioctl(raw->avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
  // Nor does simavr sleep 1 µs of wall time at each poll of the status register (the firmware
  // polls UDRE and TXC): that made a simulated second cost 8 s.
  flags &= ~static_cast<std::uint32_t>(AVR_UART_FLAG_STDIO | AVR_UART_FLAG_POLL_SLEEP);
  avr_ioctl(raw->avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
  avr_irq_register_notify(avr_io_getirq(raw->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                          Impl::uart_hook, raw);
  // Jumpers: a fitted one reads low; BAUD0/BAUD1 are analog inputs with external pull-ups.
  raw->drive_jumpers();
  for (char port : {'B', 'C'}) {
    avr_irq_register_notify(
        avr_io_getirq(raw->avr, static_cast<std::uint32_t>(AVR_IOCTL_IOPORT_GETIRQ(port)),
                      IOPORT_IRQ_REG_PORT),
        Impl::port_written, raw);
  }
  avr_raise_irq(avr_io_getirq(raw->avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC6),
                setup.baud == 9600 ? 0 : 5000);
  avr_raise_irq(avr_io_getirq(raw->avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC7),
                setup.baud == 115200 ? 0 : 5000);
  // The encoders on their pins.
  raw->data_irq = {raw->pin_irq(kAzPins.data), raw->pin_irq(kElPins.data)};
  avr_irq_register_notify(raw->pin_irq(kAzPins.clk), Impl::edge_hook<0, true>, raw);
  avr_irq_register_notify(raw->pin_irq(kAzPins.cs), Impl::edge_hook<0, false>, raw);
  avr_irq_register_notify(raw->pin_irq(kElPins.clk), Impl::edge_hook<1, true>, raw);
  avr_irq_register_notify(raw->pin_irq(kElPins.cs), Impl::edge_hook<1, false>, raw);
  avr_irq_register_notify(raw->pin_irq(kDePin), Impl::driver_hook, raw);
  raw->drive_data(0);
  raw->drive_data(1);
  auto hub = std::unique_ptr<AvrHub>(new AvrHub(std::move(impl)));
  hub->impl_->owner = hub.get();
  return hub;
}

AvrHub::AvrHub(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

AvrHub::~AvrHub() {
  if (impl_ && impl_->avr != nullptr) {
    avr_terminate(impl_->avr);
    free(impl_->avr);  // NOLINT(cppcoreguidelines-no-malloc): simavr allocates with malloc
  }
}

void AvrHub::set_counts(std::uint16_t az_raw, std::uint16_t el_raw) {
  impl_->encoders[0].set_count(az_raw);
  impl_->encoders[1].set_count(el_raw);
}

void AvrHub::set_fault(bool azimuth, EncoderFault fault) {
  const std::size_t axis = azimuth ? 0 : 1;
  impl_->encoders.at(axis).set_fault(fault);
  impl_->drive_data(axis);
}

double AvrHub::now_us() const { return impl_->now_us(); }

void AvrHub::run_for(double seconds) {
  avr_t* avr = impl_->avr;
  // The end is kept exact across calls (a 5 ms step is 80000 cycles, a step of any length adds
  // up), and a sleeping AVR wakes there: simavr skips a sleep to the next timer event, which
  // would otherwise put the AVR's clock ahead of its caller's.
  impl_->until_cycle =
      std::max(impl_->until_cycle, static_cast<double>(avr->cycle)) + seconds * kCpuHz;
  const auto end = static_cast<avr_cycle_count_t>(std::llround(impl_->until_cycle));
  if (end <= avr->cycle) return;
  avr_cycle_timer_register(avr, end - avr->cycle, &Impl::wake_at_end, nullptr);
  run_until(end);
  avr_cycle_timer_cancel(avr, &Impl::wake_at_end, nullptr);
}

void AvrHub::run_until(std::uint64_t end) {
  avr_t* avr = impl_->avr;
  while (avr->cycle < end) {
    const avr_flashaddr_t before = avr->pc;
    const int state = avr_run(avr);
    if (avr->pc == 0 && before != 0) {
      ++impl_->resets;  // the watchdog (or a jump to the reset vector) restarted the firmware
      // A reset clears simavr's pin states; the jumpers and encoders are still wired.
      impl_->stop_level_polling();
      impl_->drive_jumpers();
      for (std::size_t axis = 0; axis < 2; ++axis) {
        Impl::force(impl_->data_irq.at(axis),
                    impl_->encoders.at(axis).data(impl_->now_us()) ? 1U : 0U);
      }
      if (impl_->patched) {
        std::memcpy(avr->flash + impl_->patched->first, impl_->patched->second.data(), 2);
        impl_->patched.reset();
      }
    }
    if (state == cpu_Done || state == cpu_Crashed) break;
  }
}

void AvrHub::hang() {
  avr_t* avr = impl_->avr;
  const avr_flashaddr_t pc = avr->pc;
  std::array<std::uint8_t, 2> original{avr->flash[pc], avr->flash[pc + 1]};
  impl_->patched = std::make_pair(pc, original);
  avr->flash[pc] = 0xFF;  // rjmp .-2 (0xCFFF, little-endian): jump to itself
  avr->flash[pc + 1] = 0xCF;
}

std::uint32_t AvrHub::resets() const { return impl_->resets; }

double AvrHub::cpu_load() const {
  const Impl& i = *impl_;
  const avr_cycle_count_t span = i.avr->cycle - i.load_since_cycle;
  return !i.load_started || span == 0
             ? 0.0
             : 1.0 - static_cast<double>(i.asleep_cycles) / static_cast<double>(span);
}

}  // namespace azt::avr
