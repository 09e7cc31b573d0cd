// The EncoderHub firmware itself, the ELF the build makes, on a simulated ATmega328P (simavr,
// issue 14 §3): every resolution and code decodes exactly through the daemon's decoder, every
// encoder fault gives no false position and is reported, the watchdog recovers a hung loop, and
// the link's timing is measured in the AVR's own cycles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "azt/avr/avr_hub.hpp"
#include "azt/proto/hub_frame.hpp"

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

// The link, in simulated cycles: frames per second, the bytes' spacing at each baud rate, and
// the share of each frame period the firmware is busy (printed: the closing note's figures).
// simavr 1.6's USART ignores U2X and spends 11 bit times on a byte, so its spacing is
// 11 × 16 × (UBRR + 1) cycles where the chip's is 10 × 8 × (UBRR + 1): the test checks the
// firmware's UBRR through simavr's formula and prints what the chip does with it.
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
    for (std::size_t i = 1; i < proto::kHubCrc8FrameBytes; ++i) {
      const double gap = rig.byte_us.at(i) - rig.byte_us.at(i - 1);
      EXPECT_NEAR(gap, simavr_gap_us, 0.01 * simavr_gap_us) << baud << " byte " << i;
    }
    const double chip_baud = 16e6 / (8.0 * (ubrr + 1U));
    EXPECT_NEAR(chip_baud / baud, 1.0, 0.025) << "the chip's rate error at " << baud;
    std::printf(
        "[ measure  ] %u baud: %.2f frames/s; simavr byte every %.1f us (chip: %.1f us, "
        "%.0f baud); busy %.1f %% of the time in simavr\n",
        baud, fps, rig.byte_us.at(1) - rig.byte_us.at(0), 10e6 / chip_baud, chip_baud,
        100.0 * rig.hub->busy_fraction());
    EXPECT_LT(rig.hub->busy_fraction(), 0.9);
  }
}

}  // namespace
}  // namespace azt::avr
