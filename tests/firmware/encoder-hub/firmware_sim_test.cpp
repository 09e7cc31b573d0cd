// The EncoderHub firmware itself, the ELF the build makes, on a simulated ATmega328P (simavr,
// docs/encoder-hub.md): every resolution and code decodes exactly through the daemon's decoder,
// every encoder fault gives no false position and is reported, the watchdog recovers a hung loop,
// and the link's timing is measured in the AVR's own cycles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "azt/avr/avr_hub.hpp"
#include "azt/proto/hub_decoder.hpp"

namespace azt::avr {
namespace {

using proto::HubAxisError;
using proto::HubReading;

/// A simulated hub and the frames its USART sent, decoded as the daemon decodes them.
struct Rig {
  std::unique_ptr<AvrHub> hub;
  proto::HubDecoder decoder{proto::HubAccept::Crc8Only, proto::HubSync::AwaitDelimiter};
  std::vector<HubReading> frames;
  std::vector<double> frame_end_us;
  std::vector<double> byte_us;
  std::vector<std::pair<bool, double>> driver;  ///< DE changes: level, time (µs)
  std::function<void(const HubReading&)> on_frame;

  explicit Rig(AvrHubSetup setup) {
    setup.elf_path = AZT_HUB_ELF;
    auto loaded = AvrHub::load(setup);
    EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message);
    hub = std::move(loaded).value();
    hub->on_byte = [this](std::uint8_t b, double at_us) {
      byte_us.push_back(at_us);
      proto::HubFrame f{};
      if (decoder.push(b, f) != proto::HubFrameStatus::Ok) return;
      frames.push_back(f.reading);
      frame_end_us.push_back(at_us);
      if (on_frame) on_frame(f.reading);
    };
    hub->on_driver = [this](bool high, double at_us) { driver.emplace_back(high, at_us); };
  }
};

HubAxisSetup generic(std::uint8_t bits, bool gray) {
  return {gray ? EncoderModelKind::SsiGray : EncoderModelKind::SsiBinary, bits};
}

// §3: for each width 9..16 and both codes (azimuth Gray, elevation binary), 200 random counts
// decode exactly: each frame carries the counts the encoders had when it was read.
class EveryWidth : public ::testing::TestWithParam<int> {};

TEST_P(EveryWidth, TwoHundredRandomCountsDecodeExactlyInGrayAndBinary) {
  const auto bits = static_cast<std::uint8_t>(GetParam());
  AvrHubSetup setup;
  setup.az = generic(bits, true);
  setup.el = generic(bits, false);
  Rig rig(setup);
  std::mt19937 rng(static_cast<unsigned>(bits));
  std::uniform_int_distribution<unsigned> count(0, (1U << bits) - 1U);
  HubReading want{bits, bits, 0, 0};
  const auto next = [&] {
    want.az_raw = static_cast<std::uint16_t>(count(rng));
    want.el_raw = static_cast<std::uint16_t>(count(rng));
    rig.hub->set_counts(want.az_raw, want.el_raw);
  };
  next();
  int exact = 0;
  rig.on_frame = [&](const HubReading& r) {
    // A frame is read at its period's start and sent after: the next counts apply to the next.
    EXPECT_EQ(r, want);
    exact += r == want ? 1 : 0;
    next();
  };
  rig.hub->run_for(200 * 0.02 + 0.05);
  EXPECT_GE(rig.frames.size(), 200U);
  EXPECT_EQ(exact, static_cast<int>(rig.frames.size()));
}

INSTANTIATE_TEST_SUITE_P(Bits, EveryWidth, ::testing::Range(9, 17));

TEST(FirmwareOnAvr, TwoHundredRandomAs5045CountsDecodeExactly) {
  Rig rig(AvrHubSetup{});  // no jumpers: two AS5045-class encoders
  std::mt19937 rng(45);
  std::uniform_int_distribution<unsigned> count(0, 4095);
  HubReading want{12, 12, 0, 0};
  const auto next = [&] {
    want.az_raw = static_cast<std::uint16_t>(count(rng));
    want.el_raw = static_cast<std::uint16_t>(count(rng));
    rig.hub->set_counts(want.az_raw, want.el_raw);
  };
  next();
  rig.on_frame = [&](const HubReading& r) {
    EXPECT_EQ(r, want);
    next();
  };
  rig.hub->run_for(200 * 0.02 + 0.05);
  EXPECT_GE(rig.frames.size(), 200U);
}

// Every fault: no frame carries a count other than the true one, and the axis says why.
struct FaultCase {
  EncoderFault fault;
  EncoderModelKind kind;
  bool every_frame;  ///< the fault shows in every frame (not only in the glitched ones)
};

class EveryFault : public ::testing::TestWithParam<FaultCase> {};

TEST_P(EveryFault, NoFalsePositionAndTheAxisSaysSo) {
  const FaultCase c = GetParam();
  AvrHubSetup setup;
  setup.az = {c.kind, 13};
  Rig rig(setup);
  rig.hub->set_counts(1000, 512);
  rig.hub->set_fault(true, c.fault);
  rig.hub->run_for(0.6);
  ASSERT_GE(rig.frames.size(), 25U);
  int reported = 0;
  for (const HubReading& r : rig.frames) {
    if (r.az_error == HubAxisError::None) {
      EXPECT_EQ(r.az_raw, 1000) << "a false position";
    } else {
      ++reported;
    }
    EXPECT_EQ(r.el_error, HubAxisError::None) << "the healthy axis was spoiled";
    EXPECT_EQ(r.el_raw, 512);
  }
  if (c.every_frame) {
    EXPECT_EQ(reported, static_cast<int>(rig.frames.size()));
  } else {
    EXPECT_GT(reported, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Faults, EveryFault,
    ::testing::Values(FaultCase{EncoderFault::Stuck, EncoderModelKind::As5045, true},
                      FaultCase{EncoderFault::Open, EncoderModelKind::As5045, true},
                      FaultCase{EncoderFault::Flip, EncoderModelKind::As5045, true},
                      FaultCase{EncoderFault::Glitch, EncoderModelKind::As5045, false},
                      FaultCase{EncoderFault::Stuck, EncoderModelKind::SsiGray, true},
                      FaultCase{EncoderFault::Open, EncoderModelKind::SsiGray, true},
                      FaultCase{EncoderFault::Flip, EncoderModelKind::SsiGray, true},
                      FaultCase{EncoderFault::Glitch, EncoderModelKind::SsiBinary, false}));

TEST(FirmwareOnAvr, TheWatchdogRecoversAHungLoopWithin250ms) {
  Rig rig(AvrHubSetup{});
  rig.hub->set_counts(100, 200);
  rig.hub->run_for(0.2);
  const std::size_t before = rig.frames.size();
  ASSERT_GE(before, 8U);
  const double hung_at_us = rig.hub->now_us();
  rig.hub->hang();
  rig.hub->run_for(0.5);
  EXPECT_EQ(rig.hub->resets(), 1U);
  ASSERT_GT(rig.frames.size(), before) << "no frame after the hang";
  const double back_after_ms = (rig.frame_end_us.at(before) - hung_at_us) / 1000.0;
  std::printf("[ measure  ] hung loop: next frame after %.1f ms (watchdog resets: %u)\n",
              back_after_ms, rig.hub->resets());
  EXPECT_LT(back_after_ms, 250.0);
  EXPECT_EQ(rig.frames.back(), (HubReading{12, 12, 100, 200}));
}

/// DE is driven low (receive) from start-up, rises before each frame's first byte and falls
/// once its last byte's stop bit has left (simavr reports a byte as it starts; its byte time is
/// rounded, hence 1 %), within an interrupt's time. A frame still on the wire is left out.
void expect_driver_covers_each_frame(const Rig& rig, double byte_us, double isr_us) {
  const std::size_t frame_bytes = proto::kHubCrc8FrameBytes;
  const std::size_t frames = (rig.driver.size() - 1) / 2;
  ASSERT_GE(frames, rig.byte_us.size() / frame_bytes - 1);
  EXPECT_FALSE(rig.driver.front().first);
  EXPECT_LT(rig.driver.front().second, rig.byte_us.front());
  for (std::size_t f = 0; f < frames; ++f) {
    const auto& [rise_high, rise_us] = rig.driver.at(1 + 2 * f);
    const auto& [fall_high, fall_us] = rig.driver.at(2 + 2 * f);
    ASSERT_TRUE(rise_high && !fall_high) << "frame " << f;
    const double first_us = rig.byte_us.at(f * frame_bytes);
    const double last_end_us = rig.byte_us.at((f + 1) * frame_bytes - 1) + byte_us;
    EXPECT_LE(rise_us, first_us) << "frame " << f;
    EXPECT_GE(fall_us, last_end_us - 0.01 * byte_us)
        << "frame " << f << ": DE dropped inside the last byte";
    EXPECT_LE(fall_us, last_end_us + isr_us) << "frame " << f;
  }
}

// The link, in simulated cycles: frames per second, the bytes' spacing at each baud rate, the
// RS-485 driver's timing, and the CPU's load (printed: the closing note's figures).
// simavr 1.6's USART ignores U2X and spends 11 bit times on a byte, so its spacing is
// 11 × 16 × (UBRR + 1) cycles where the chip's is 10 × 8 × (UBRR + 1): the test checks the
// firmware's UBRR through simavr's formula and prints what the chip does with it. simavr has no
// transmit buffer behind UDR0, so each byte also waits for the interrupt that loads it (a few µs;
// on the chip the buffer hides it).
TEST(FirmwareOnAvr, FrameRateByteTimingAndLoad) {
  for (std::uint32_t baud : {9600U, 38400U, 115200U}) {
    AvrHubSetup setup;
    setup.baud = baud;
    Rig rig(setup);
    rig.hub->set_counts(1, 2);
    rig.hub->run_for(0.5);
    ASSERT_GE(rig.frame_end_us.size(), 10U);
    const double span_s = (rig.frame_end_us.back() - rig.frame_end_us.front()) / 1e6;
    const double fps = static_cast<double>(rig.frame_end_us.size() - 1) / span_s;
    EXPECT_NEAR(fps, 50.0, 0.5) << baud;
    const unsigned ubrr = (16000000U / 8U + baud / 2U) / baud - 1U;  // U2X, as the firmware
    const double simavr_gap_us = 11.0 * 16.0 * (ubrr + 1U) / 16.0;
    constexpr double kIsrUs = 4.0;  // an interrupt's entry, the byte's load and its exit
    for (std::size_t i = 1; i < proto::kHubCrc8FrameBytes; ++i) {
      const double gap = rig.byte_us.at(i) - rig.byte_us.at(i - 1);
      EXPECT_GE(gap, simavr_gap_us) << baud << " byte " << i;
      EXPECT_LE(gap, simavr_gap_us + kIsrUs) << baud << " byte " << i;
    }
    expect_driver_covers_each_frame(rig, simavr_gap_us, kIsrUs);
    const double chip_baud = 16e6 / (8.0 * (ubrr + 1U));
    EXPECT_NEAR(chip_baud / baud, 1.0, 0.025) << "the chip's rate error at " << baud;
    std::printf(
        "[ measure  ] %u baud: %.2f frames/s; simavr byte every %.1f us (chip: %.1f us, "
        "%.0f baud); CPU awake %.2f %% of the time\n",
        baud, fps, rig.byte_us.at(1) - rig.byte_us.at(0), 10e6 / chip_baud, chip_baud,
        100.0 * rig.hub->cpu_load());
    EXPECT_GT(rig.hub->cpu_load(), 0.0);
    EXPECT_LT(rig.hub->cpu_load(), 0.1) << "the CPU should sleep while the frame is sent";
  }
}

}  // namespace
}  // namespace azt::avr
