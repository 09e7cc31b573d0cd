// From two reads per axis to the frame the hub sends (docs/encoder-hub.md): the agreement window on
// a circle of counts, and errors in place of positions, through the daemon's own decoder.
#include "hub_reading.hpp"

#include <gtest/gtest.h>

#include "reading_agreement.hpp"

namespace azt::hub {
namespace {

using proto::HubAxisError;

TEST(ReadingAgreement, CountsAreOnACircle) {
  EXPECT_EQ(count_distance(0, 4095, 12), 1);
  EXPECT_EQ(count_distance(4095, 0, 12), 1);
  EXPECT_EQ(count_distance(10, 14, 12), 4);
  EXPECT_EQ(count_distance(0, 2048, 12), 2048);
  EXPECT_EQ(count_distance(0, 65535, 16), 1);
}

TEST(ReadingAgreement, TwoReadsAgreeWithinTheWindowOrTheAxisSaysSo) {
  const SsiCount a{4094, HubAxisError::None};
  EXPECT_EQ(agreed_count(a, SsiCount{2, HubAxisError::None}, 12, 4).raw, 4094);
  EXPECT_EQ(agreed_count(a, SsiCount{3, HubAxisError::None}, 12, 4).error, HubAxisError::Disagree);
  EXPECT_EQ(agreed_count(SsiCount{0, HubAxisError::Parity}, a, 12, 4).error, HubAxisError::Parity);
  EXPECT_EQ(agreed_count(a, SsiCount{0, HubAxisError::NoEncoder}, 12, 4).error,
            HubAxisError::NoEncoder);
}

TEST(HubReading, ErrorsReplacePositionsAndTheDaemonDecodesThem) {
  const HubJumpers j = read_jumpers(0);  // two AS5045s
  const proto::HubReading good =
      hub_reading(j, SsiCount{100, HubAxisError::None}, SsiCount{200, HubAxisError::None});
  EXPECT_EQ(good, (proto::HubReading{12, 12, 100, 200}));
  const proto::HubReading bad =
      hub_reading(j, SsiCount{100, HubAxisError::None}, SsiCount{0, HubAxisError::Linearity});
  EXPECT_EQ(bad.el_bits, 0);
  EXPECT_EQ(bad.el_error, HubAxisError::Linearity);
  uint8_t frame[proto::kHubMaxFrameBytes] = {};
  const size_t n = proto::encode_hub_frame(bad, proto::HubFrameVersion::Crc8, frame, sizeof frame);
  ASSERT_EQ(n, proto::kHubCrc8FrameBytes);
  proto::HubFrame out{};
  ASSERT_EQ(proto::decode_hub_chunk(frame, n - 1, proto::HubAccept::Crc8Only, out),
            proto::HubFrameStatus::Ok);
  EXPECT_EQ(out.reading, bad);
  // Jumpers that select nothing known: every frame says so for that axis.
  const HubJumpers unknown = read_jumpers(0x18U);  // az TYPE0 and TYPE1
  EXPECT_EQ(hub_reading(unknown, SsiCount{5, HubAxisError::None}, SsiCount{5, HubAxisError::None})
                .az_error,
            HubAxisError::BadJumpers);
}

}  // namespace
}  // namespace azt::hub
