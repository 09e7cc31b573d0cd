// COBS as the EncoderHub frames use it: the vectors of the Wikipedia article the seed cites (after
// Cheshire & Baker, IEEE/ACM Trans. Networking 7(2), 1999), the longest payload, malformed chunks.
#include "azt/proto/hub_cobs.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "proto/hub_bytes.hpp"

namespace azt::proto {
namespace {

using hub_test::Bytes;

TEST(HubCobs, WikipediaExamples) {
  // "Consistent Overhead Byte Stuffing", Wikipedia, encoding examples 1-6 (delimiter omitted).
  const std::vector<std::pair<Bytes, Bytes>> cases = {
      {{0x00}, {0x01, 0x01}},
      {{0x00, 0x00}, {0x01, 0x01, 0x01}},
      {{0x00, 0x11, 0x00}, {0x01, 0x02, 0x11, 0x01}},
      {{0x11, 0x22, 0x00, 0x33}, {0x03, 0x11, 0x22, 0x02, 0x33}},
      {{0x11, 0x22, 0x33, 0x44}, {0x05, 0x11, 0x22, 0x33, 0x44}},
      {{0x11, 0x00, 0x00, 0x00}, {0x02, 0x11, 0x01, 0x01, 0x01}},
      {{}, {0x01}},
  };
  for (const auto& [payload, encoded] : cases) {
    uint8_t out[16] = {};
    const size_t n = hub_cobs_encode(payload.data(), payload.size(), out, sizeof out);
    EXPECT_EQ(Bytes(out, out + n), encoded);
    uint8_t back[16] = {};
    size_t decoded = 99;
    ASSERT_TRUE(hub_cobs_decode(encoded.data(), encoded.size(), back, sizeof back, decoded));
    EXPECT_EQ(Bytes(back, back + decoded), payload);
  }
}

TEST(HubCobs, LongestPayloadWithoutTheFFCode) {
  // 253 non-zero bytes: one block, code 0xFE. 254 would need the 0xFF code: refused, as the seed
  // limits its packets to fewer than 254 bytes.
  Bytes payload(253);
  for (size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<uint8_t>(1 + i % 255);
  Bytes out(300);
  ASSERT_EQ(hub_cobs_encode(payload.data(), payload.size(), out.data(), out.size()), 254U);
  EXPECT_EQ(out[0], 0xFE);
  Bytes back(300);
  size_t decoded = 0;
  ASSERT_TRUE(hub_cobs_decode(out.data(), 254, back.data(), back.size(), decoded));
  EXPECT_EQ(Bytes(back.begin(), back.begin() + static_cast<long>(decoded)), payload);
  payload.push_back(0x01);
  EXPECT_EQ(hub_cobs_encode(payload.data(), payload.size(), out.data(), out.size()), 0U);
  EXPECT_EQ(hub_cobs_encode(payload.data(), 3, out.data(), 3), 0U);  // output too small
}

TEST(HubCobs, DecodeRejectsMalformedChunks) {
  uint8_t out[16] = {};
  size_t n = 0;
  const Bytes past_end = {0x04, 0x11, 0x22};
  const Bytes zero_code = {0x02, 0x11, 0x00, 0x22};
  const Bytes zero_data = {0x03, 0x11, 0x00};  // nanocobs #43: an embedded zero is not data
  const Bytes ff_code = {0xFF, 0x11};
  EXPECT_FALSE(hub_cobs_decode(past_end.data(), past_end.size(), out, sizeof out, n));
  EXPECT_FALSE(hub_cobs_decode(zero_code.data(), zero_code.size(), out, sizeof out, n));
  EXPECT_FALSE(hub_cobs_decode(zero_data.data(), zero_data.size(), out, sizeof out, n));
  EXPECT_FALSE(hub_cobs_decode(ff_code.data(), ff_code.size(), out, sizeof out, n));
  const Bytes fine = {0x03, 0x11, 0x22, 0x02, 0x33};
  EXPECT_FALSE(hub_cobs_decode(fine.data(), fine.size(), out, 3, n));  // output too small
  EXPECT_TRUE(hub_cobs_decode(fine.data(), fine.size(), out, 4, n));
}

}  // namespace
}  // namespace azt::proto
