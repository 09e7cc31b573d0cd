// An EncoderHub reading's numbers (seed 000, "Encoder Resolution calculations"): counts to degrees,
// the resolution nibbles of the EncBITS byte.
#include "azt/proto/hub_reading.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace azt::proto {
namespace {

TEST(HubResolution, DegreesMatchTheSeedsTable) {
  // Seed 000 "Encoder Resolution calculations", printed to 4-5 decimals (truncated, not rounded).
  EXPECT_NEAR(hub_raw_to_deg(1, 12), 0.0879, 1e-4);
  EXPECT_NEAR(hub_raw_to_deg(2, 12), 0.1757, 1e-4);
  EXPECT_NEAR(hub_raw_to_deg(1, 13), 0.0439, 1e-4);
  EXPECT_NEAR(hub_raw_to_deg(2, 13), 0.0878, 1e-4);
  EXPECT_NEAR(hub_raw_to_deg(1, 16), 0.00549, 1e-5);
  EXPECT_NEAR(hub_raw_to_deg(2, 16), 0.01098, 1e-5);
  EXPECT_EQ(hub_resolution_deg(12), 0.087890625);  // 360 / 4096, exact in binary
}

TEST(HubResolution, SixteenBitsDivideBy65536NotTheSeeds65535) {
  // With 65535 the largest count would read exactly 360°, the direction of count 0.
  EXPECT_EQ(hub_raw_to_deg(65535, 16), 359.9945068359375);  // 360 - 360/65536
  EXPECT_LT(hub_raw_to_deg(65535, 16), 360.0);
  EXPECT_EQ(hub_raw_to_deg(32768, 16), 180.0);
}

TEST(HubResolution, InvalidArgumentsGiveNoAngle) {
  EXPECT_EQ(hub_raw_to_deg(0, 8), -1.0);
  EXPECT_EQ(hub_raw_to_deg(0, 17), -1.0);
  EXPECT_EQ(hub_raw_to_deg(512, 9), -1.0);
  EXPECT_EQ(hub_raw_to_deg(0, 255), -1.0);
  EXPECT_EQ(hub_resolution_deg(17), -1.0);
  EXPECT_EQ(hub_raw_limit(255), 0U);
}

TEST(HubNibbles, SixteenIsZeroAndOneToEightAreInvalid) {
  for (unsigned nibble = 0; nibble < 16; ++nibble) {
    const uint8_t bits = hub_nibble_to_bits(static_cast<uint8_t>(nibble));
    if (nibble == 0) {
      EXPECT_EQ(bits, 16);
    } else if (nibble >= 9) {
      EXPECT_EQ(bits, nibble);
    } else {
      EXPECT_EQ(bits, 0) << nibble;
    }
  }
  for (uint8_t bits = 9; bits <= 16; ++bits) {
    EXPECT_EQ(hub_nibble_to_bits(hub_bits_to_nibble(bits)), bits);
  }
  EXPECT_EQ(hub_enc_bits(12, 13), 0xCD);
  EXPECT_EQ(hub_enc_bits(16, 9), 0x09);
  EXPECT_EQ(hub_enc_bits(9, 16), 0x90);
}

}  // namespace
}  // namespace azt::proto
