// EncoderHub frames (seed 000, "Encoder Hub Data Format"): frames derived by hand, both versions
// round trip at every resolution, the axis errors of our CRC-8 frames, and what one corrupted byte
// does to a seed frame and to a CRC frame through decode_hub_chunk.
#include "azt/proto/hub_frame.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "proto/hub_bytes.hpp"

namespace azt::proto {
namespace {

using hub_test::Bytes;
using hub_test::concat;
using hub_test::encode;
using hub_test::Fed;
using hub_test::feed;
using hub_test::frame_of;
using hub_test::status_of;

TEST(HubFrameExamples, TwelveBitEncodersAsTheSeedsHH12) {
  // az 12 bits raw 2048 (0x0800), el 12 bits raw 1024 (0x0400). EncBITS = 0xC << 4 | 0xC.
  // Payload CC 04 00 08 00 -> blocks [CC 04] [08] [] -> 03 CC 04 02 08 01, then 00:
  // the seed's DATA[7], its FRAME_START being the first code byte.
  const HubReading r{12, 12, 2048, 1024};
  const Bytes expected = {0x03, 0xCC, 0x04, 0x02, 0x08, 0x01, 0x00};
  EXPECT_EQ(encode(r, HubFrameVersion::Seed), expected);
  EXPECT_EQ(expected.size(), kHubSeedFrameBytes);
  HubDecoder d(HubAccept::SeedOnly, HubSync::InSync);
  const Fed fed = feed(d, expected);
  ASSERT_EQ(fed.frames.size(), 1U);
  EXPECT_EQ(fed.frames[0].reading, r);
  EXPECT_EQ(fed.frames[0].version, HubFrameVersion::Seed);
  // 2048 of 4096 steps is half a turn, 1024 a quarter.
  EXPECT_EQ(hub_raw_to_deg(r.az_raw, r.az_bits), 180.0);
  EXPECT_EQ(hub_raw_to_deg(r.el_raw, r.el_bits), 90.0);
}

TEST(HubFrameExamples, SixteenBitsTravelAsNibbleZero) {
  // Both 16 bits: EncBITS 0x00. az 0xFFFF, el 0x1234. Payload 00 12 34 FF FF ->
  // blocks [] [12 34 FF FF] -> 01 05 12 34 FF FF, then 00.
  const HubReading r{16, 16, 0xFFFF, 0x1234};
  EXPECT_EQ(encode(r, HubFrameVersion::Seed), (Bytes{0x01, 0x05, 0x12, 0x34, 0xFF, 0xFF, 0x00}));
}

TEST(HubFrameExamples, NineAndFifteenBitsAtTheirLargestCounts) {
  // az 9 bits raw 511 (0x01FF), el 15 bits raw 32767 (0x7FFF): EncBITS 0x9F, no zero byte,
  // one block of five: 06 9F 7F FF 01 FF, then 00.
  const HubReading r{9, 15, 511, 32767};
  const Bytes frame = {0x06, 0x9F, 0x7F, 0xFF, 0x01, 0xFF, 0x00};
  EXPECT_EQ(encode(r, HubFrameVersion::Seed), frame);
  EXPECT_EQ(status_of(frame), HubFrameStatus::Ok);
  // One step short of a full turn: 360 - 360/512 and 360 - 360/32768.
  EXPECT_EQ(hub_raw_to_deg(r.az_raw, r.az_bits), 359.296875);
  EXPECT_EQ(hub_raw_to_deg(r.el_raw, r.el_bits), 359.989013671875);
}

TEST(HubFrameExamples, Crc8Version) {
  // The HH12 payload CC 04 00 08 00 plus its CRC-8/AUTOSAR, 0x6C (computed by polynomial long
  // division in Python, which gives the catalogue check value). Payload CC 04 00 08 00 6C ->
  // blocks [CC 04] [08] [6C] -> 03 CC 04 02 08 02 6C, then 00.
  const HubReading r{12, 12, 2048, 1024};
  const Bytes expected = {0x03, 0xCC, 0x04, 0x02, 0x08, 0x02, 0x6C, 0x00};
  EXPECT_EQ(encode(r, HubFrameVersion::Crc8), expected);
  EXPECT_EQ(expected.size(), kHubCrc8FrameBytes);
  EXPECT_EQ(kHubMaxFrameBytes, 8U);
  HubDecoder d(HubAccept::Crc8Only, HubSync::InSync);
  const Fed fed = feed(d, expected);
  ASSERT_EQ(fed.frames.size(), 1U);
  EXPECT_EQ(fed.frames[0].reading, r);
  EXPECT_EQ(fed.frames[0].version, HubFrameVersion::Crc8);
  EXPECT_EQ(d.counters().frames_crc8, 1U);
  EXPECT_EQ(d.counters().frames_seed, 0U);
}

TEST(HubFrameRoundTrip, EveryResolutionPairBothVersions) {
  std::mt19937_64 rng(0x485542);  // "HUB"
  int frames = 0;
  for (uint8_t az_bits = 9; az_bits <= 16; ++az_bits) {
    for (uint8_t el_bits = 9; el_bits <= 16; ++el_bits) {
      const uint32_t az_limit = uint32_t{1} << az_bits;
      const uint32_t el_limit = uint32_t{1} << el_bits;
      std::vector<HubReading> readings = {{az_bits, el_bits, 0, 0},
                                          {az_bits, el_bits, static_cast<uint16_t>(az_limit - 1),
                                           static_cast<uint16_t>(el_limit - 1)}};
      for (int i = 0; i < 20; ++i) {
        readings.push_back({az_bits, el_bits, static_cast<uint16_t>(rng() % az_limit),
                            static_cast<uint16_t>(rng() % el_limit)});
      }
      for (const HubFrameVersion version : {HubFrameVersion::Seed, HubFrameVersion::Crc8}) {
        for (const HubReading& r : readings) {
          const Bytes frame = encode(r, version);
          ASSERT_EQ(frame.size(), version == HubFrameVersion::Seed ? 7U : 8U);
          for (size_t i = 0; i + 1 < frame.size(); ++i) ASSERT_NE(frame[i], 0) << i;
          ASSERT_EQ(frame.back(), 0);
          HubDecoder d(HubAccept::Any);  // awaits a delimiter: lead with one
          const Fed fed = feed(d, concat({0x00}, frame));
          ASSERT_EQ(fed.frames.size(), 1U);
          EXPECT_EQ(fed.frames[0].reading, r);
          EXPECT_EQ(fed.frames[0].version, version);
          EXPECT_GE(hub_raw_to_deg(r.az_raw, r.az_bits), 0.0);
          EXPECT_LT(hub_raw_to_deg(r.el_raw, r.el_bits), 360.0);
          ++frames;
        }
      }
    }
  }
  EXPECT_EQ(frames, 8 * 8 * 22 * 2);
}

TEST(HubFrameRoundTrip, EncoderRefusesWhatTheDecoderWouldReject) {
  uint8_t buf[kHubMaxFrameBytes] = {};
  const auto seed = HubFrameVersion::Seed;
  EXPECT_EQ(encode_hub_frame({8, 12, 0, 0}, seed, buf, sizeof buf), 0U);
  EXPECT_EQ(encode_hub_frame({12, 17, 0, 0}, seed, buf, sizeof buf), 0U);
  EXPECT_EQ(encode_hub_frame({0, 0, 0, 0}, seed, buf, sizeof buf), 0U);
  EXPECT_EQ(encode_hub_frame({9, 12, 512, 0}, seed, buf, sizeof buf), 0U);
  EXPECT_EQ(encode_hub_frame({9, 12, 0, 4096}, seed, buf, sizeof buf), 0U);
  EXPECT_EQ(encode_hub_frame({9, 12, 511, 4095}, seed, buf, sizeof buf), 7U);
  EXPECT_EQ(encode_hub_frame({9, 12, 511, 4095}, seed, buf, 6), 0U);
  EXPECT_EQ(encode_hub_frame({9, 12, 511, 4095}, HubFrameVersion::Crc8, buf, 7), 0U);
  EXPECT_EQ(encode_hub_frame({9, 12, 511, 4095}, seed, nullptr, 8), 0U);
}

// docs/encoder-hub.md: our CRC-8 frames say why an axis has no position (nibble 1, the code as its
// raw); the other axis still travels. The seed version cannot carry it: the encoder refuses.
TEST(HubAxisErrors, TravelInCrcFramesWithTheOtherAxisIntact) {
  for (uint8_t code = 1; code <= kHubAxisErrorLast; ++code) {
    HubReading r{12, 0, 1234, 0};
    r.el_error = static_cast<HubAxisError>(code);
    const Bytes frame = encode(r, HubFrameVersion::Crc8);
    ASSERT_EQ(frame.size(), kHubCrc8FrameBytes) << int(code);
    HubDecoder d(HubAccept::Crc8Only, HubSync::InSync);
    const Fed fed = feed(d, frame);
    ASSERT_EQ(fed.frames.size(), 1U) << int(code);
    EXPECT_EQ(fed.frames[0].reading, r);
    EXPECT_TRUE(hub_reading_has_error(fed.frames[0].reading));
    EXPECT_STRNE(hub_axis_error_name(r.el_error), "unknown error");
    EXPECT_TRUE(encode(r, HubFrameVersion::Seed).empty()) << "a seed frame cannot say it";
  }
  HubReading both{0, 0, 0, 0, HubAxisError::NoEncoder, HubAxisError::Parity};
  EXPECT_EQ(status_of(encode(both, HubFrameVersion::Crc8)), HubFrameStatus::Ok);
}

TEST(HubAxisErrors, MalformedErrorAxesAreRejected) {
  // Nibble 1 in a seed frame stays a bad nibble, as the seed's format has it.
  EXPECT_EQ(status_of(frame_of({0x1C, 0x00, 0x01, 0x00, 0x02})), HubFrameStatus::BadNibble);
  // In a CRC frame: code 0 means no error, so nibble 1 with it names no resolution; a code
  // past the last is out of range.
  const auto crc_frame = [](Bytes payload) {
    payload.push_back(hub_crc8(payload.data(), payload.size()));
    return frame_of(payload);
  };
  EXPECT_EQ(status_of(crc_frame({0x1C, 0x00, 0x01, 0x00, 0x00})), HubFrameStatus::BadNibble);
  EXPECT_EQ(status_of(crc_frame({0x1C, 0x00, 0x01, 0x00, kHubAxisErrorLast + 1})),
            HubFrameStatus::OutOfRange);
  EXPECT_EQ(status_of(crc_frame({0x1C, 0x00, 0x01, 0x00, 0x02})), HubFrameStatus::Ok);
  // An error axis with a resolution or a count is not a reading the encoder makes.
  HubReading mixed{12, 12, 0, 5};
  mixed.az_error = HubAxisError::Parity;
  EXPECT_TRUE(encode(mixed, HubFrameVersion::Crc8).empty());
}

TEST(HubCorruption, SingleByteErrorsThroughTheDecoder) {
  // hub_crc8_test.cpp's single-byte errors through decode_hub_chunk, on random valid readings, with
  // the seed version beside it: a seed frame has no guard against these errors, which is why our
  // hub sends CRC frames.
  std::mt19937_64 rng(0x5EED);
  int seed_accepted = 0;
  int crc_checked = 0;
  for (int k = 0; k < 300; ++k) {
    const auto bits = [&rng]() { return static_cast<uint8_t>(9 + rng() % 8); };
    HubReading r{bits(), bits(), 0, 0};
    r.az_raw = static_cast<uint16_t>(rng() % (uint32_t{1} << r.az_bits));
    r.el_raw = static_cast<uint16_t>(rng() % (uint32_t{1} << r.el_bits));
    for (const HubFrameVersion version : {HubFrameVersion::Seed, HubFrameVersion::Crc8}) {
      const Bytes frame = encode(r, version);
      const HubAccept accept =
          version == HubFrameVersion::Crc8 ? HubAccept::Crc8Only : HubAccept::SeedOnly;
      for (size_t pos = 0; pos + 1 < frame.size(); ++pos) {
        for (unsigned value = 1; value < 256; ++value) {
          if (value == frame[pos]) continue;
          Bytes hit = frame;
          hit[pos] = static_cast<uint8_t>(value);
          HubFrame out{};
          const HubFrameStatus s = decode_hub_chunk(hit.data(), hit.size() - 1, accept, out);
          if (version == HubFrameVersion::Seed) {
            seed_accepted += s == HubFrameStatus::Ok ? 1 : 0;
          } else {
            ASSERT_NE(s, HubFrameStatus::Ok) << "byte " << pos << " -> " << value;
            ++crc_checked;
          }
        }
      }
    }
  }
  EXPECT_EQ(crc_checked, 300 * 7 * 254);
  EXPECT_GT(seed_accepted, 0);
  RecordProperty("seed_single_byte_errors_accepted", seed_accepted);
}

}  // namespace
}  // namespace azt::proto
