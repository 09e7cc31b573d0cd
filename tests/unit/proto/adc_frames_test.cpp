// ADC wire formats (docs/hardware.md), with the datasheets' own examples.
#include "azt/proto/adc_frames.hpp"

#include <gtest/gtest.h>

namespace azt::proto {
namespace {

TEST(Mcp3008, RequestAndReplyBytes) {
  // DS21295 table 5-2: single-ended CH0 is control bits 1000, CH7 is 1111.
  EXPECT_EQ(*mcp3008_request(0), (std::array<std::uint8_t, 3>{0x01, 0x80, 0x00}));
  EXPECT_EQ(*mcp3008_request(7), (std::array<std::uint8_t, 3>{0x01, 0xF0, 0x00}));
  EXPECT_FALSE(mcp3008_request(8).has_value());
  // The null bit and B9 B8 end the second byte; bits above them are undefined on the wire.
  EXPECT_EQ(mcp3008_code({0xFF, 0xFB, 0x2C}), 0x32C);
  EXPECT_EQ(mcp3008_code({0x00, 0x03, 0xFF}), 1023);
}

TEST(Ads1115, SingleShotConfigOfTheDatasheetsDefaults) {
  // SBAS444 §8.6.3: the reset value 0x8583 is AIN0/AIN1 differential, ±2.048 V, single-shot,
  // 128 SPS, comparator off. AIN0 against GND (MUX 100) at the same settings is 0xC583.
  EXPECT_EQ(*ads1115_single_shot_config(0, Ads1115Range::Fs2V048), 0xC583);
  // AIN3 (MUX 111) at ±6.144 V (PGA 000): 0xF183.
  EXPECT_EQ(*ads1115_single_shot_config(3, Ads1115Range::Fs6V144), 0xF183);
  EXPECT_FALSE(ads1115_single_shot_config(4, Ads1115Range::Fs4V096).has_value());
  EXPECT_EQ(ads1115_write(kAds1115PointerConfig, 0xC583),
            (std::array<std::uint8_t, 3>{0x01, 0xC5, 0x83}));
}

TEST(Ads1115, ConversionResultsAreSigned) {
  EXPECT_TRUE(ads1115_ready({0x85, 0x83}));
  EXPECT_FALSE(ads1115_ready({0x05, 0x83}));
  EXPECT_EQ(ads1115_code({0x7F, 0xFF}), 32767);  // positive full scale
  EXPECT_EQ(ads1115_code({0x80, 0x00}), -32768);
  EXPECT_EQ(ads1115_code({0xFF, 0xFF}), -1);
  // 2.5 V at ±6.144 V: 2.5 / 187.5 µV = 13333 counts.
  EXPECT_NEAR(13333 * ads1115_volts_per_count(Ads1115Range::Fs6V144), 2.5, 1e-3);
}

}  // namespace
}  // namespace azt::proto
