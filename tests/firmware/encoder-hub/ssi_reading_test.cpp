// The hub firmware's SSI word checks (docs/encoder-hub.md), compiled for the host from the
// firmware's own header: AS5045 words built bit by bit as the datasheet lays them out, every status
// and line fault, and Gray code both ways at every width.
#include "ssi_reading.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace azt::hub {
namespace {

using proto::HubAxisError;

/// An AS5045 word from its fields, MSB first as the wire has them (datasheet "Data Content").
uint32_t by_hand(uint16_t raw, bool ocf, bool cof, bool lin, bool inc, bool dec) {
  uint32_t w = 0;
  for (int i = 11; i >= 0; --i) w = (w << 1U) | ((raw >> i) & 1U);
  for (bool b : {ocf, cof, lin, inc, dec}) w = (w << 1U) | (b ? 1U : 0U);
  unsigned ones_count = 0;
  for (int i = 0; i < 17; ++i) ones_count += (w >> i) & 1U;
  return (w << 1U) | (ones_count % 2U);  // even parity: the 18 bits hold an even number of ones
}

TEST(As5045, AGoodWordGivesItsCount) {
  for (uint16_t raw : {uint16_t{0}, uint16_t{1}, uint16_t{2047}, uint16_t{2048}, uint16_t{4095}}) {
    const uint32_t w = by_hand(raw, true, false, false, false, false);
    EXPECT_EQ(make_as5045_word(raw, true, false, false, false, false), w);
    const SsiCount c = decode_as5045(w, true, true);
    EXPECT_EQ(c.error, HubAxisError::None) << raw;
    EXPECT_EQ(c.raw, raw);
  }
  // MagINC or MagDEC alone says the magnet moves in Z, not that the angle is bad.
  EXPECT_EQ(decode_as5045(by_hand(77, true, false, false, true, false), true, true).raw, 77);
  EXPECT_EQ(decode_as5045(by_hand(77, true, false, false, false, true), true, true).raw, 77);
}

TEST(As5045, EachStatusFaultIsNamedAndGivesNoCount) {
  const struct {
    uint32_t word;
    HubAxisError error;
  } cases[] = {
      {by_hand(100, false, false, false, false, false), HubAxisError::NotReady},
      {by_hand(100, true, true, false, false, false), HubAxisError::CordicOverflow},
      {by_hand(100, true, false, true, false, false), HubAxisError::Linearity},
      {by_hand(100, true, false, false, true, true), HubAxisError::MagnetRange},
  };
  for (const auto& c : cases) {
    const SsiCount r = decode_as5045(c.word, true, true);
    EXPECT_EQ(r.error, c.error);
    EXPECT_EQ(r.raw, 0);
  }
}

TEST(As5045, EverySingleFlippedBitIsAParityError) {
  const uint32_t good = by_hand(1234, true, false, false, false, false);
  for (unsigned bit = 0; bit < kAs5045WordBits; ++bit) {
    EXPECT_EQ(decode_as5045(good ^ (1UL << bit), true, true).error, HubAxisError::Parity) << bit;
  }
}

TEST(As5045, AnUndrivenOrStuckLineIsNoEncoder) {
  EXPECT_EQ(decode_as5045(kAs5045AllOnes, true, true).error, HubAxisError::NoEncoder);
  EXPECT_EQ(decode_as5045(0, false, true).error, HubAxisError::NoEncoder);  // stuck low
}

TEST(GenericSsi, GrayAndBinaryAtEveryWidth) {
  for (uint8_t bits = 9; bits <= 16; ++bits) {
    const uint32_t top = proto::hub_raw_limit(bits) - 1U;
    for (uint32_t raw : {0U, 1U, 2U, top / 3U, top / 2U, top - 1U, top}) {
      const auto r16 = static_cast<uint16_t>(raw);
      EXPECT_EQ(gray_to_binary(binary_to_gray(r16)), r16);
      const SsiCount b = decode_generic_ssi(raw, bits, EncoderCode::Binary, true, true);
      const SsiCount g =
          decode_generic_ssi(binary_to_gray(r16), bits, EncoderCode::Gray, true, true);
      EXPECT_EQ(b.error, HubAxisError::None);
      EXPECT_EQ(b.raw, raw) << int(bits);
      EXPECT_EQ(g.raw, raw) << int(bits);
    }
  }
  // Neighbouring counts differ in one Gray bit (why absolute encoders use it).
  for (uint16_t v = 0; v < 1000; ++v) {
    const auto diff = static_cast<uint16_t>(binary_to_gray(v) ^ binary_to_gray(v + 1));
    EXPECT_EQ(ones(diff, 16), 1) << v;
  }
}

TEST(GenericSsi, LineFaultsAreNoEncoderWhateverTheWord) {
  for (bool idle : {false, true}) {
    for (bool trailer : {false, true}) {
      const SsiCount c = decode_generic_ssi(0x155, 12, EncoderCode::Binary, idle, trailer);
      EXPECT_EQ(c.error == HubAxisError::None, idle && trailer);
      if (!(idle && trailer)) {
        EXPECT_EQ(c.error, HubAxisError::NoEncoder);
      }
    }
  }
}

}  // namespace
}  // namespace azt::hub
