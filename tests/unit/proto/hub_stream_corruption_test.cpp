// Seeded random EncoderHub streams with 5 % of their bytes (or frames) corrupted, through the
// streaming decoder: every intact frame arrives, a corrupted one never takes another's place, and
// on a CRC-8 link no frame with one bad byte is accepted.
#include "azt/proto/hub_decoder.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "proto/hub_bytes.hpp"

namespace azt::proto {
namespace {

using hub_test::Bytes;
using hub_test::encode;

/// A seeded stream of valid frames in which every byte is replaced, with probability 5 %, by a
/// different random value; the decoder's verdict on every chunk is checked against what was done
/// to it.
struct StreamReport {
  size_t frames_sent = 0;
  size_t intact_chunks = 0;         // both delimiters and every byte between them untouched
  size_t intact_accepted = 0;       // ... and decoded to the reading that was sent
  size_t corrupted_chunks = 0;      // at least one byte touched (delimiters included)
  size_t accepted_one_error = 0;    // corrupted chunks accepted, exactly one byte touched
  size_t accepted_more_errors = 0;  // corrupted chunks accepted, two or more bytes touched
  size_t delimiters = 0;
  HubCounters counters{};
};

/// How the 5 % corruption is spread: over bytes (bursts of several bad bytes in one frame happen)
/// or over frames (each corrupted frame has exactly one bad byte, delimiter included).
enum class Corruption { PerByte, PerFrame };

StreamReport run_stream(uint64_t seed, HubFrameVersion version, HubAccept accept, size_t frames,
                        Corruption how = Corruption::PerByte) {
  std::mt19937_64 rng(seed);
  Bytes stream = {0x37, 0x91, 0x05};  // stray bytes at connect time
  std::vector<int> frame_ending_at(stream.size(), -1);
  std::vector<HubReading> sent;
  for (size_t k = 0; k < frames; ++k) {
    const auto bits = [&rng]() { return static_cast<uint8_t>(9 + rng() % 8); };
    HubReading r{bits(), bits(), 0, 0};
    r.az_raw = static_cast<uint16_t>(rng() % (uint32_t{1} << r.az_bits));
    r.el_raw = static_cast<uint16_t>(rng() % (uint32_t{1} << r.el_bits));
    const Bytes f = encode(r, version);
    stream.insert(stream.end(), f.begin(), f.end());
    frame_ending_at.resize(stream.size(), -1);
    frame_ending_at.back() = static_cast<int>(sent.size());
    sent.push_back(r);
  }
  std::vector<bool> touched(stream.size(), false);
  const auto corrupt = [&](size_t i) {
    stream[i] = static_cast<uint8_t>(stream[i] ^ (1 + rng() % 255));
    touched[i] = true;
  };
  if (how == Corruption::PerByte) {
    for (size_t i = 0; i < stream.size(); ++i) {
      if (rng() % 100 < 5) corrupt(i);
    }
  } else {
    size_t frame_start = 3;  // after the stray bytes
    for (size_t i = frame_start; i < stream.size(); ++i) {
      if (frame_ending_at[i] < 0) continue;
      if (rng() % 100 < 5) corrupt(frame_start + rng() % (i + 1 - frame_start));
      frame_start = i + 1;
    }
  }
  StreamReport rep;
  rep.frames_sent = frames;
  HubDecoder d(accept);
  size_t chunk_open = 0;  // index of the delimiter that opened the current chunk
  bool synced = false;
  for (size_t i = 0; i < stream.size(); ++i) {
    HubFrame out{};
    const HubFrameStatus s = d.push(stream[i], out);
    if (stream[i] != 0) continue;
    ++rep.delimiters;
    const size_t open = chunk_open;
    chunk_open = i;
    if (!synced) {
      synced = true;
      EXPECT_NE(s, HubFrameStatus::Ok);  // the start-up chunk is never taken
      continue;
    }
    size_t errors = 0;
    for (size_t j = open; j <= i; ++j) errors += touched[j] ? 1U : 0U;
    if (s == HubFrameStatus::Ok) {
      // Accepted means a canonical frame of a valid reading, corrupted or not.
      EXPECT_TRUE(hub_reading_valid(out.reading));
      EXPECT_EQ(encode(out.reading, out.version),
                Bytes(stream.begin() + static_cast<long>(open) + 1,
                      stream.begin() + static_cast<long>(i) + 1));
      EXPECT_LT(hub_raw_to_deg(out.reading.az_raw, out.reading.az_bits), 360.0);
      EXPECT_GE(hub_raw_to_deg(out.reading.el_raw, out.reading.el_bits), 0.0);
    }
    if (errors == 0) {
      ++rep.intact_chunks;
      const int k = frame_ending_at[i];
      const bool right =
          s == HubFrameStatus::Ok && k >= 0 && out.reading == sent[static_cast<size_t>(k)];
      rep.intact_accepted += right ? 1 : 0;
    } else {
      ++rep.corrupted_chunks;
      if (s == HubFrameStatus::Ok)
        (errors == 1 ? rep.accepted_one_error : rep.accepted_more_errors)++;
    }
  }
  rep.counters = d.counters();
  return rep;
}

void record(const StreamReport& rep, const std::string& prefix) {
  testing::Test::RecordProperty(prefix + "_frames_sent", std::to_string(rep.frames_sent));
  testing::Test::RecordProperty(prefix + "_corrupted_chunks", std::to_string(rep.corrupted_chunks));
  testing::Test::RecordProperty(prefix + "_accepted_one_error",
                                std::to_string(rep.accepted_one_error));
  testing::Test::RecordProperty(prefix + "_accepted_more_errors",
                                std::to_string(rep.accepted_more_errors));
  testing::Test::RecordProperty(prefix + "_bad_crc", std::to_string(rep.counters.bad_crc));
}

void expect_common(const StreamReport& rep) {
  // Every intact frame arrives, a corrupted one never takes another's place, and each delimiter
  // is accounted for exactly once.
  EXPECT_GT(rep.intact_chunks, rep.frames_sent / 2);
  EXPECT_EQ(rep.intact_accepted, rep.intact_chunks);
  EXPECT_EQ(rep.counters.chunks(), rep.delimiters);
  EXPECT_GT(rep.corrupted_chunks, rep.frames_sent / 5);
}

TEST(HubCorruption, SeedStreamAcceptsOnlyWellFormedFrames) {
  const StreamReport rep = run_stream(0xA27E1, HubFrameVersion::Seed, HubAccept::SeedOnly, 20000);
  expect_common(rep);
  // Without a check byte, some corrupted frames are well-formed and get through: each one is
  // still a valid reading (checked in run_stream), which is all a seed-version link can promise;
  // the jump filter downstream has to catch the rest.
  EXPECT_GT(rep.accepted_one_error + rep.accepted_more_errors, 0U);
  record(rep, "seed");
}

TEST(HubCorruption, Crc8StreamRejectsCorruptedFrames) {
  const StreamReport rep = run_stream(0xA27E1, HubFrameVersion::Crc8, HubAccept::Crc8Only, 20000);
  expect_common(rep);
  // Guaranteed: no frame with a single corrupted byte is accepted (hub_crc8_test.cpp). Two or more
  // corrupted bytes in one frame are caught only with probability 255/256, like any 8-bit check:
  // this seeded stream lets one such frame through in 20000 (reported below), so the bound is on
  // the rate, at least 31 in 32 of the corrupted frames that reach the CRC caught. The jump filter
  // downstream sees the rest.
  EXPECT_EQ(rep.accepted_one_error, 0U);
  EXPECT_LE(rep.accepted_more_errors * 32, rep.counters.bad_crc);
  EXPECT_GT(rep.counters.bad_crc, 0U);
  record(rep, "crc8");
}

TEST(HubCorruption, Crc8StreamWithFivePercentOfFramesCorruptedAcceptsNone) {
  // 5 % of the frames each hit by one bad byte (code, data, CRC or delimiter): CRC-8/AUTOSAR
  // catches every single-byte error, so not one corrupted frame may be accepted.
  const StreamReport rep =
      run_stream(0x5EED5, HubFrameVersion::Crc8, HubAccept::Crc8Only, 20000, Corruption::PerFrame);
  EXPECT_EQ(rep.intact_accepted, rep.intact_chunks);
  EXPECT_GT(rep.corrupted_chunks, 20000U * 4 / 100);
  EXPECT_EQ(rep.accepted_one_error + rep.accepted_more_errors, 0U);
  record(rep, "crc8_per_frame");
}

TEST(HubCorruption, AnyPolicyOnACrcLinkKeepsTheStreamProperties) {
  // With Any, corruption can turn a CRC frame into a seed frame (the worked example in
  // hub_decoder_test.cpp); in a random stream it takes a 16/16-bit frame and a zeroed code byte, so
  // it is rare: reported, and the properties every policy must keep are checked.
  const StreamReport rep = run_stream(0xA27E1, HubFrameVersion::Crc8, HubAccept::Any, 20000);
  expect_common(rep);
  RecordProperty("crc8_any_downgraded_to_seed", std::to_string(rep.counters.frames_seed));
  record(rep, "crc8_any");
}

}  // namespace
}  // namespace azt::proto
