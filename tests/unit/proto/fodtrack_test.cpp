// FODTRACK parallel-port decoding (docs/hardware.md). The sender side follows Hamlib's fodtrack.c:
// data, then AUTOFEED for the axis, then a STROBE pulse; elevation is sent before azimuth.
#include "azt/proto/fodtrack.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace azt::proto {
namespace {

/// The line states a FODTRACK program produces for one axis, sampled twice per state.
std::vector<ParallelSample> send(std::uint8_t data, bool azimuth) {
  std::vector<ParallelSample> out;
  for (const bool strobe : {false, true, true, false}) {
    out.push_back(ParallelSample{data, strobe, azimuth});
    out.push_back(ParallelSample{data, strobe, azimuth});
  }
  return out;
}

TEST(Fodtrack, LatchesEachAxisOncePerStrobePulse) {
  FodtrackDecoder d;  // the seed's interface: 0–360° azimuth, 0–90° elevation
  int latches = 0;
  for (const auto& s : send(FodtrackDecoder::encode(45.0, 90.0), false))
    latches += d.feed(s) ? 1 : 0;
  for (const auto& s : send(FodtrackDecoder::encode(200.0, 360.0), true))
    latches += d.feed(s) ? 1 : 0;
  EXPECT_EQ(latches, 2);
  ASSERT_TRUE(d.az_deg() && d.el_deg());
  EXPECT_NEAR(*d.az_deg(), 200.0, 360.0 / 255.0);
  EXPECT_NEAR(*d.el_deg(), 45.0, 90.0 / 255.0);
}

TEST(Fodtrack, DataWithoutStrobeIsIgnored) {
  FodtrackDecoder d;
  for (std::uint8_t b = 0; b < 255; ++b) EXPECT_FALSE(d.feed(ParallelSample{b, false, true}));
  EXPECT_FALSE(d.az_deg().has_value());
}

TEST(Fodtrack, ResolutionIsWhatEightBitsAllow) {
  const FodtrackScale seed{};
  EXPECT_NEAR(seed.az_step_deg(), 1.41, 0.005);  // the seed's "best possible definition"
  EXPECT_NEAR(seed.el_step_deg(), 0.353, 0.001);
  // Every angle a program sends comes back within one step below it (the byte is truncated).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> az(0.0, 360.0);
  FodtrackDecoder d(seed);
  for (int i = 0; i < 1000; ++i) {
    const double a = az(rng);
    for (const auto& s : send(FodtrackDecoder::encode(a, 360.0), true)) d.feed(s);
    ASSERT_TRUE(d.az_deg());
    EXPECT_LE(*d.az_deg(), a + 1e-9);
    EXPECT_GT(*d.az_deg(), a - seed.az_step_deg());
  }
}

TEST(Fodtrack, ScalesAreThePrograms) {
  auto hamlib = FodtrackScale::make(450.0, 180.0);  // Hamlib's default caps
  ASSERT_TRUE(hamlib.ok());
  FodtrackDecoder d(*hamlib);
  for (const auto& s : send(255, true)) d.feed(s);
  EXPECT_DOUBLE_EQ(*d.az_deg(), 450.0);
  EXPECT_FALSE(FodtrackScale::make(0.0, 90.0).ok());
  EXPECT_FALSE(FodtrackScale::make(360.0, 1e6).ok());
  EXPECT_EQ(FodtrackDecoder::encode(-5.0, 360.0), 0);
  EXPECT_EQ(FodtrackDecoder::encode(999.0, 360.0), 255);
}

}  // namespace
}  // namespace azt::proto
