// The hub's jumpers (docs/encoder-hub.md), from the firmware's own header: every combination of one
// axis's five, the baud pair, and the default with none fitted.
#include "jumpers.hpp"

#include <gtest/gtest.h>

namespace azt::hub {
namespace {

TEST(Jumpers, NoneFittedIsTwoAs5045sAt38400) {
  const HubJumpers j = read_jumpers(0);
  EXPECT_EQ(j.az.kind, EncoderKind::As5045);
  EXPECT_EQ(j.az.bits, 12);
  EXPECT_EQ(j.el.kind, EncoderKind::As5045);
  EXPECT_EQ(j.baud, 38400U);
  EXPECT_EQ(word_bits(j.az), 18);
}

TEST(Jumpers, EveryCombinationOfOneAxis) {
  for (uint8_t five = 0; five < 32; ++five) {
    const AxisJumpers a = axis_jumpers(five);
    const unsigned type = five >> 3U;
    const auto expected_bits = static_cast<uint8_t>(9 + (five & 7U));
    switch (type) {
      case 0:
        EXPECT_EQ(a.kind, EncoderKind::As5045) << int(five);
        EXPECT_EQ(a.bits, 12);
        break;
      case 1:
        EXPECT_EQ(a.kind, EncoderKind::GenericSsi);
        EXPECT_EQ(a.code, EncoderCode::Binary);
        EXPECT_EQ(a.bits, expected_bits);
        EXPECT_EQ(word_bits(a), expected_bits);
        break;
      case 2:
        EXPECT_EQ(a.kind, EncoderKind::GenericSsi);
        EXPECT_EQ(a.code, EncoderCode::Gray);
        EXPECT_EQ(a.bits, expected_bits);
        break;
      default:
        EXPECT_EQ(a.kind, EncoderKind::Unknown) << int(five);
    }
  }
}

TEST(Jumpers, AxesAndBaudComeFromTheirOwnBits) {
  // az: generic Gray 16 bits (RES = 7, TYPE1); el: generic binary 9 bits (TYPE0); baud0.
  const uint16_t fitted = static_cast<uint16_t>((0x17U << kJumperAzShift) |
                                                (0x08U << kJumperElShift) | (1U << kJumperBaud0));
  const HubJumpers j = read_jumpers(fitted);
  EXPECT_EQ(j.az.kind, EncoderKind::GenericSsi);
  EXPECT_EQ(j.az.code, EncoderCode::Gray);
  EXPECT_EQ(j.az.bits, 16);
  EXPECT_EQ(j.el.code, EncoderCode::Binary);
  EXPECT_EQ(j.el.bits, 9);
  EXPECT_EQ(j.baud, 9600U);
  EXPECT_EQ(read_jumpers(1U << kJumperBaud1).baud, 115200U);
  EXPECT_EQ(read_jumpers((1U << kJumperBaud0) | (1U << kJumperBaud1)).baud, 38400U);
}

}  // namespace
}  // namespace azt::hub
