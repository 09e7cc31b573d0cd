// SPID Rot2Prog/Rot1Prog server codec: the byte examples from
// reference/rotator-controllers-and-protocols.md §8.4, rejection cases, resynchronisation and
// seeded round trips.
#include "azt/proto/spid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace azt::proto {
namespace {

TEST(Spid, SetFrameFromReference) {
  // az 123.5, el 77.0, PH = PV = 2 -> H = 967, V = 874.
  const SpidFrame expected{0x57, 0x30, 0x39, 0x36, 0x37, 0x02, 0x30,
                           0x38, 0x37, 0x34, 0x02, 0x2F, 0x20};
  auto encoded = encode_spid_set(123.5, 77.0);
  ASSERT_TRUE(encoded.ok());
  EXPECT_EQ(*encoded, expected);
  auto cmd = parse_spid(expected);
  ASSERT_TRUE(cmd.ok()) << cmd.error().message;
  EXPECT_EQ(*cmd, (SpidCommand{SpidOp::Set, 123.5, 77.0}));
}

TEST(Spid, StatusReplyFromReference) {
  const std::array<std::uint8_t, 12> expected{0x57, 0x03, 0x07, 0x02, 0x05, 0x02,
                                              0x03, 0x09, 0x04, 0x00, 0x02, 0x20};
  auto reply = format_spid_rot2_reply(12.5, 34.0);
  ASSERT_TRUE(reply.ok());
  EXPECT_EQ(*reply, expected);
}

TEST(Spid, StopAndStatusAsHamlibSendsThem) {
  // Hamlib fills the data bytes of stop and status frames with zeros.
  const SpidFrame stop{0x57, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x0F, 0x20};
  const SpidFrame status{0x57, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x1F, 0x20};
  EXPECT_EQ(parse_spid(stop)->op, SpidOp::Stop);
  EXPECT_EQ(parse_spid(status)->op, SpidOp::Status);
}

TEST(Spid, Rot1Prog) {
  SpidConfig rot1{SpidDialect::Rot1Prog};
  auto frame = encode_spid_set(123.0, 0.0, rot1);
  ASSERT_TRUE(frame.ok());
  const SpidFrame expected{0x57, '4', '8', '3', '0', 0, 0, 0, 0, 0, 0, 0x2F, 0x20};
  EXPECT_EQ(*frame, expected);
  EXPECT_EQ(*parse_spid(expected, rot1), (SpidCommand{SpidOp::Set, 123.0, 0.0}));
  const std::array<std::uint8_t, 5> reply{0x57, 0x04, 0x08, 0x03, 0x20};
  EXPECT_EQ(*format_spid_rot1_reply(123.0), reply);
}

TEST(Spid, Rejects) {
  const SpidFrame good{0x57, 0x30, 0x39, 0x36, 0x37, 0x02, 0x30,
                       0x38, 0x37, 0x34, 0x02, 0x2F, 0x20};
  EXPECT_FALSE(parse_spid(std::span<const std::uint8_t>(good).first(12)).ok());
  for (std::size_t i : {0u, 1u, 4u, 6u, 9u, 11u, 12u}) {
    SpidFrame bad = good;
    bad[i] = 0x3A;  // ':' is not a digit, start, K or end
    EXPECT_FALSE(parse_spid(bad).ok()) << "byte " << i;
  }
  SpidFrame far = good;
  far[1] = '1';  // H = 1967 -> az 623.5
  EXPECT_FALSE(parse_spid(far).ok());
  SpidFrame low = good;
  low[6] = '0';
  low[7] = '6';  // V = 0674 -> el -23
  EXPECT_FALSE(parse_spid(low).ok());
  SpidConfig bad_res;
  bad_res.pulses_per_deg_az = 3;
  EXPECT_FALSE(parse_spid(good, bad_res).ok());
  EXPECT_FALSE(format_spid_rot2_reply(std::nan(""), 0.0).ok());
  EXPECT_FALSE(format_spid_rot2_reply(700.0, 0.0).ok());
  EXPECT_FALSE(format_spid_rot2_reply(0.0, -400.0).ok());
  EXPECT_FALSE(encode_spid_set(INFINITY, 0.0).ok());
  EXPECT_FALSE(format_spid_rot1_reply(NAN).ok());
}

TEST(Spid, AssemblerResynchronises) {
  SpidFrameAssembler assembler;
  const SpidFrame status{0x57, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x1F, 0x20};
  std::vector<std::uint8_t> stream = {0x00, 0x13, 0x57, 0x31, 0x57};  // noise, a torn frame
  stream.insert(stream.end(), status.begin(), status.end());
  std::vector<SpidFrame> frames;
  for (std::uint8_t b : stream) {
    if (auto f = assembler.push(b)) frames.push_back(*f);
    EXPECT_LE(assembler.pending_bytes(), kSpidCommandBytes);
  }
  // The torn "W1W..." is dropped once its 13 bytes fail; the real frame is found after it.
  for (std::size_t i = 0; i < kSpidCommandBytes; ++i) {
    if (auto f = assembler.push(status[i])) frames.push_back(*f);
  }
  ASSERT_GE(frames.size(), 1u);
  EXPECT_EQ(frames.back(), status);
  EXPECT_GE(assembler.dropped_bytes(), 2u);
  // Garbage without 'W' never accumulates.
  SpidFrameAssembler quiet;
  for (int i = 0; i < 1000; ++i) EXPECT_FALSE(quiet.push(0x20));
  EXPECT_EQ(quiet.pending_bytes(), 0u);
  EXPECT_EQ(quiet.dropped_bytes(), 1000u);
}

TEST(Spid, SeededRandomFramesNeverCrash) {
  std::mt19937_64 rng(0x5B1D'0BAD);
  std::uniform_int_distribution<int> byte(0, 255);
  SpidFrameAssembler assembler;
  for (int i = 0; i < 20000; ++i) {
    // Bias towards the bytes that matter so frames do occur.
    int b = byte(rng);
    if (b < 40) b = 0x57;
    if (b >= 40 && b < 60) b = 0x20;
    if (auto frame = assembler.push(static_cast<std::uint8_t>(b))) {
      EXPECT_EQ((*frame)[0], kSpidStart);
      EXPECT_EQ((*frame)[12], kSpidEnd);
      auto cmd = parse_spid(*frame);
      if (cmd && cmd->op == SpidOp::Set) {
        EXPECT_GE(cmd->az_deg, -180.0);
        EXPECT_LE(cmd->az_deg, 540.0);
      }
    }
    ASSERT_LT(assembler.pending_bytes(), kSpidCommandBytes);
  }
}

TEST(Spid, SeededRoundTrip) {
  std::mt19937_64 rng(0x5B1D'0002);
  std::uniform_int_distribution<int> res_pick(0, 2);
  const int kRes[] = {1, 2, 4};
  for (int i = 0; i < 3000; ++i) {
    SpidConfig config;
    config.pulses_per_deg_az = kRes[res_pick(rng)];
    config.pulses_per_deg_el = kRes[res_pick(rng)];
    std::uniform_int_distribution<int> az_steps(-180 * config.pulses_per_deg_az,
                                                540 * config.pulses_per_deg_az);
    std::uniform_int_distribution<int> el_steps(-20 * config.pulses_per_deg_el,
                                                210 * config.pulses_per_deg_el);
    // Targets on the controller's grid survive Hamlib's truncating encoding exactly.
    const double az = az_steps(rng) / static_cast<double>(config.pulses_per_deg_az);
    const double el = el_steps(rng) / static_cast<double>(config.pulses_per_deg_el);
    auto frame = encode_spid_set(az, el, config);
    ASSERT_TRUE(frame.ok());
    auto cmd = parse_spid(*frame, config);
    ASSERT_TRUE(cmd.ok()) << cmd.error().message;
    EXPECT_DOUBLE_EQ(cmd->az_deg, az);
    EXPECT_DOUBLE_EQ(cmd->el_deg, el);
    // The status reply decodes (as Hamlib does) to the position rounded to 0.1 degree.
    auto reply = format_spid_rot2_reply(az, el, config);
    ASSERT_TRUE(reply.ok());
    const auto& r = *reply;
    const double az_back = r[1] * 100 + r[2] * 10 + r[3] + r[4] / 10.0 - 360.0;
    const double el_back = r[6] * 100 + r[7] * 10 + r[8] + r[9] / 10.0 - 360.0;
    EXPECT_NEAR(az_back, az, 0.05 + 1e-9);
    EXPECT_NEAR(el_back, el, 0.05 + 1e-9);
    EXPECT_EQ(r[5], config.pulses_per_deg_az);
    EXPECT_EQ(r[10], config.pulses_per_deg_el);
  }
}

}  // namespace
}  // namespace azt::proto
