// The EncoderHub's streaming decoder: every rejection kind, one at a time (each 0x00 adds exactly
// one to exactly one counter), reset, and resync after garbage.
#include "azt/proto/hub_decoder.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <set>
#include <string>
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

TEST(HubDecoderRejects, EmptyChunksAreCountedButAreNotErrors) {
  HubDecoder d(HubAccept::Any, HubSync::InSync);
  const Fed fed = feed(d, {0x00, 0x00});
  EXPECT_EQ(fed.outcomes,
            (std::vector<HubFrameStatus>{HubFrameStatus::Empty, HubFrameStatus::Empty}));
  EXPECT_EQ(d.counters().empty, 2U);
  EXPECT_EQ(d.counters().rejected(), 0U);
  EXPECT_EQ(d.counters().chunks(), 2U);
}

TEST(HubDecoderRejects, BytesBeforeTheFirstDelimiterAreUnsynced) {
  const Bytes frame = encode({12, 12, 2048, 1024}, HubFrameVersion::Seed);
  HubDecoder d(HubAccept::Any);
  // A valid frame whose start we missed: its tail is discarded, the next frame is taken.
  const Bytes tail(frame.begin() + 3, frame.end());
  const Fed fed = feed(d, concat(tail, frame));
  EXPECT_EQ(fed.outcomes,
            (std::vector<HubFrameStatus>{HubFrameStatus::Unsynced, HubFrameStatus::Ok}));
  EXPECT_EQ(d.counters().unsynced, 1U);
  EXPECT_EQ(d.counters().rejected(), 0U);
  // A whole frame before the first delimiter is discarded too: we cannot know it was whole.
  HubDecoder whole(HubAccept::Any);
  EXPECT_EQ(feed(whole, frame).outcomes.front(), HubFrameStatus::Unsynced);
  // A leading delimiter is an empty chunk, not an unsynced one.
  HubDecoder lead(HubAccept::Any);
  EXPECT_EQ(feed(lead, concat({0x00}, frame)).outcomes,
            (std::vector<HubFrameStatus>{HubFrameStatus::Empty, HubFrameStatus::Ok}));
  // In sync from the start (a capture file): the first frame counts.
  HubDecoder in_sync(HubAccept::Any, HubSync::InSync);
  EXPECT_EQ(feed(in_sync, frame).frames.size(), 1U);
}

TEST(HubDecoderRejects, OverlongChunksThenResyncOnTheNextDelimiter) {
  HubDecoder d(HubAccept::Any, HubSync::InSync);
  const Bytes frame = encode({12, 12, 2048, 1024}, HubFrameVersion::Seed);
  Bytes run(300, 0x5A);  // a 300-byte non-zero run (reliability notes, R04)
  run.push_back(0x00);
  const Fed fed = feed(d, concat(run, frame));
  EXPECT_EQ(fed.outcomes,
            (std::vector<HubFrameStatus>{HubFrameStatus::Overlong, HubFrameStatus::Ok}));
  EXPECT_EQ(d.counters().overlong, 1U);
  // Eight bytes are one too many; seven are a CRC frame's length: seven 0x01 decode to six
  // zeros, a 16/16-bit reading of 0/0 whose check byte would have to be 0x4D, not 0.
  EXPECT_EQ(status_of({0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x00}),
            HubFrameStatus::Overlong);
  EXPECT_EQ(status_of({0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x00}), HubFrameStatus::BadCrc);
}

TEST(HubDecoderRejects, WrongLengths) {
  const Bytes frame = encode({12, 12, 2048, 1024}, HubFrameVersion::Seed);
  Bytes truncated = frame;
  truncated.erase(truncated.begin() + 2);  // a byte lost on the line
  HubDecoder d(HubAccept::Any, HubSync::InSync);
  EXPECT_EQ(feed(d, truncated).outcomes.front(), HubFrameStatus::WrongLength);
  EXPECT_EQ(d.counters().wrong_length, 1U);
  EXPECT_EQ(status_of({0x01, 0x00}), HubFrameStatus::WrongLength);
  EXPECT_EQ(status_of({0x05, 0x11, 0x22, 0x33, 0x44, 0x00}), HubFrameStatus::WrongLength);
}

TEST(HubDecoderRejects, BadCobs) {
  HubDecoder d(HubAccept::Any, HubSync::InSync);
  // Right length, but the second code (05) points past the end; then a first code of 07 on six
  // bytes; then the 0xFF code, which no frame this short can contain.
  const Bytes bad = {0x03, 0xCC, 0x04, 0x05, 0x08, 0x01, 0x00, 0x07, 0xCC, 0x04, 0x01,
                     0x08, 0x01, 0x00, 0xFF, 0x01, 0x02, 0x03, 0x04, 0x05, 0x00};
  const Fed fed = feed(d, bad);
  EXPECT_EQ(fed.outcomes, std::vector<HubFrameStatus>(3, HubFrameStatus::BadCobs));
  EXPECT_EQ(d.counters().bad_cobs, 3U);
}

TEST(HubDecoderRejects, WrongVersionForThePolicy) {
  const HubReading r{12, 12, 2048, 1024};
  HubDecoder crc_only(HubAccept::Crc8Only, HubSync::InSync);
  EXPECT_EQ(feed(crc_only, encode(r, HubFrameVersion::Seed)).outcomes.front(),
            HubFrameStatus::WrongVersion);
  EXPECT_EQ(crc_only.counters().wrong_version, 1U);
  HubDecoder seed_only(HubAccept::SeedOnly, HubSync::InSync);
  EXPECT_EQ(feed(seed_only, encode(r, HubFrameVersion::Crc8)).outcomes.front(),
            HubFrameStatus::WrongVersion);
  EXPECT_EQ(status_of(encode(r, HubFrameVersion::Seed), HubAccept::Any), HubFrameStatus::Ok);
  EXPECT_EQ(status_of(encode(r, HubFrameVersion::Crc8), HubAccept::Any), HubFrameStatus::Ok);
}

TEST(HubDecoderRejects, BadCrc) {
  // The worked CRC example with its check byte 0x6C turned into 0x6D.
  HubDecoder d(HubAccept::Crc8Only, HubSync::InSync);
  const Fed fed = feed(d, {0x03, 0xCC, 0x04, 0x02, 0x08, 0x02, 0x6D, 0x00});
  EXPECT_EQ(fed.outcomes.front(), HubFrameStatus::BadCrc);
  EXPECT_EQ(d.counters().bad_crc, 1U);
}

TEST(HubDecoderRejects, EveryEncBitsValue) {
  // Raws of 1 are valid at every resolution, so only the nibbles decide. Valid nibbles are 0
  // (16 bits) and 9..15: 8 x 8 = 64 of the 256 EncBITS values.
  int ok = 0;
  HubDecoder d(HubAccept::Any, HubSync::InSync);
  for (unsigned enc = 0; enc < 256; ++enc) {
    const Bytes frame = frame_of({static_cast<uint8_t>(enc), 0x00, 0x01, 0x00, 0x01});
    const unsigned az = enc >> 4U;
    const unsigned el = enc & 0x0FU;
    const bool valid = (az == 0 || az >= 9) && (el == 0 || el >= 9);
    const Fed fed = feed(d, frame);
    ASSERT_EQ(fed.outcomes.size(), 1U);
    EXPECT_EQ(fed.outcomes[0], valid ? HubFrameStatus::Ok : HubFrameStatus::BadNibble) << enc;
    ok += valid ? 1 : 0;
  }
  EXPECT_EQ(ok, 64);
  EXPECT_EQ(d.counters().frames_seed, 64U);
  EXPECT_EQ(d.counters().bad_nibble, 192U);
}

TEST(HubDecoderRejects, RawsAtOrAbove2PowBits) {
  HubDecoder d(HubAccept::Any, HubSync::InSync);
  for (unsigned bits = 9; bits <= 15; ++bits) {
    const unsigned limit = 1U << bits;
    const auto enc = static_cast<uint8_t>(bits << 4U | bits);
    const auto hi = [](unsigned v) { return static_cast<uint8_t>(v >> 8U); };
    const auto lo = [](unsigned v) { return static_cast<uint8_t>(v & 0xFFU); };
    // Largest valid count on both axes, then one too many on azimuth, then on elevation.
    const unsigned top = limit - 1;
    EXPECT_EQ(feed(d, frame_of({enc, hi(top), lo(top), hi(top), lo(top)})).outcomes.front(),
              HubFrameStatus::Ok);
    EXPECT_EQ(feed(d, frame_of({enc, hi(top), lo(top), hi(limit), lo(limit)})).outcomes.front(),
              HubFrameStatus::OutOfRange);
    EXPECT_EQ(feed(d, frame_of({enc, hi(limit), lo(limit), hi(top), lo(top)})).outcomes.front(),
              HubFrameStatus::OutOfRange);
  }
  EXPECT_EQ(d.counters().out_of_range, 14U);
  EXPECT_EQ(d.counters().frames_ok(), 7U);
}

TEST(HubDecoderRejects, StatusNamesAreDistinct) {
  std::set<std::string> names;
  for (int s = 0; s <= static_cast<int>(HubFrameStatus::OutOfRange); ++s) {
    names.insert(hub_status_name(static_cast<HubFrameStatus>(s)));
  }
  EXPECT_EQ(names.size(), 11U);
  EXPECT_EQ(std::string(hub_status_name(HubFrameStatus::BadCrc)), "bad_crc");
}

TEST(HubDecoder, ResetRestoresTheStartUpState) {
  HubDecoder d(HubAccept::Any);
  feed(d, {0x11, 0x00, 0x00});
  EXPECT_EQ(d.counters().chunks(), 2U);
  d.reset();
  EXPECT_EQ(d.counters().chunks(), 0U);
  // Awaiting a delimiter again: a frame straight after reset() is discarded.
  EXPECT_EQ(feed(d, encode({12, 12, 1, 1}, HubFrameVersion::Seed)).outcomes.front(),
            HubFrameStatus::Unsynced);
}

TEST(HubDecoderResync, GarbageThenDelimiterCostsNoFrame) {
  std::mt19937_64 rng(7);
  const Bytes frame = encode({14, 10, 9000, 700}, HubFrameVersion::Crc8);
  for (size_t garbage = 1; garbage <= 40; ++garbage) {
    Bytes stream;
    for (size_t i = 0; i < garbage; ++i) stream.push_back(static_cast<uint8_t>(1 + rng() % 255));
    stream.push_back(0x00);
    HubDecoder d(HubAccept::Crc8Only, HubSync::InSync);
    const Fed fed = feed(d, concat(stream, frame));
    ASSERT_EQ(fed.outcomes.size(), 2U);
    EXPECT_NE(fed.outcomes[0], HubFrameStatus::Ok);
    EXPECT_EQ(fed.outcomes[1], HubFrameStatus::Ok) << garbage;
  }
}

TEST(HubDecoderResync, GarbageWithoutDelimiterCostsExactlyOneFrame) {
  // Stray bytes glued to the front of a frame spoil that frame only (electricui-embedded #180).
  const Bytes a = encode({12, 12, 100, 200}, HubFrameVersion::Seed);
  const Bytes b = encode({12, 12, 101, 201}, HubFrameVersion::Seed);
  for (size_t garbage = 1; garbage <= 10; ++garbage) {
    HubDecoder d(HubAccept::Any, HubSync::InSync);
    const Fed fed = feed(d, concat(concat(Bytes(garbage, 0x42), a), b));
    ASSERT_EQ(fed.outcomes.size(), 2U);
    EXPECT_NE(fed.outcomes[0], HubFrameStatus::Ok);
    ASSERT_EQ(fed.frames.size(), 1U);
    EXPECT_EQ(fed.frames[0].reading, (HubReading{12, 12, 101, 201}));
  }
}

TEST(HubDecoderResync, ZeroedCodeByteDowngradesACrcFrameUnlessCrc8Only) {
  // az 16 bits raw 0x2301, el 16 bits raw 0x9C01: payload 00 9C 01 23 01, CRC 0x34 (polynomial
  // division in Python), frame 01 06 9C 01 23 01 34 00. A noise hit that zeroes the first byte
  // leaves 06 9C 01 23 01 34: a well-formed SEED frame, az 9 bits raw 0x0134, el 12 bits raw
  // 0x0123. Only a decoder that accepts nothing but CRC frames catches it.
  const Bytes frame = encode({16, 16, 0x2301, 0x9C01}, HubFrameVersion::Crc8);
  ASSERT_EQ(frame, (Bytes{0x01, 0x06, 0x9C, 0x01, 0x23, 0x01, 0x34, 0x00}));
  Bytes hit = frame;
  hit[0] = 0x00;
  HubDecoder any(HubAccept::Any, HubSync::InSync);
  const Fed fed = feed(any, hit);
  ASSERT_EQ(fed.frames.size(), 1U);
  EXPECT_EQ(fed.frames[0].version, HubFrameVersion::Seed);
  EXPECT_EQ(fed.frames[0].reading, (HubReading{9, 12, 0x0134, 0x0123}));
  HubDecoder crc_only(HubAccept::Crc8Only, HubSync::InSync);
  EXPECT_EQ(feed(crc_only, hit).outcomes,
            (std::vector<HubFrameStatus>{HubFrameStatus::Empty, HubFrameStatus::WrongVersion}));
}

}  // namespace
}  // namespace azt::proto
