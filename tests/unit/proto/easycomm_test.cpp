// EasyComm I/II server codec: transcripts from reference/rotator-controllers-and-protocols.md §8.3
// (server test vectors, Hamlib's set line, the seed's Nova/WISP "AZxxx.x ELxx.x"), rejection
// cases and seeded round trips.
#include "azt/proto/easycomm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace azt::proto {
namespace {

// Feeds `bytes` through the assembler and answers every complete line, as a server would.
std::string serve(std::string_view bytes, const EasyCommState& state,
                  EasyCommVersion version = EasyCommVersion::Two,
                  const EasyCommReplyOptions& options = {}) {
  BoundedLineAssembler assembler = make_easycomm_assembler();
  std::string out;
  for (char c : bytes) {
    auto line = assembler.push(c);
    if (!line) continue;
    auto parsed = parse_easycomm(*line, version);
    if (parsed) out += format_easycomm_reply(*parsed, state, options);
  }
  return out;
}

const EasyCommState kAt{123.4, 45.0, 2, 0, "azeltrack-1"};

TEST(EasyComm, ServerTranscripts) {
  EXPECT_EQ(serve("AZ\n", kAt), "AZ123.4\n");  // Hamlib >= 4.6, split query
  EXPECT_EQ(serve("EL\n", kAt), "EL45.0\n");
  EXPECT_EQ(serve("AZ EL\n", kAt), "AZ123.4 EL45.0\n");  // Hamlib < 4.6
  EXPECT_EQ(serve("AZ EL \n", kAt), "AZ123.4 EL45.0\n");
  EXPECT_EQ(serve("AZ200.0 EL30.0\n", kAt), "");
  EXPECT_EQ(serve("SA SE \n", kAt), "");
  EXPECT_EQ(serve("VE\n", kAt), "VEazeltrack-1\n");
  EXPECT_EQ(serve("GS\n", kAt), "GS2\n");
  EXPECT_EQ(serve("GE\r", kAt), "GE0\n");
  EXPECT_EQ(serve("AZ\r\nEL\r\n", kAt), "AZ123.4\nEL45.0\n");  // CRLF: empty line ignored
}

TEST(EasyComm, StopEchoOption) {
  EXPECT_EQ(serve("SA SE\n", kAt, EasyCommVersion::Two, {true, true}), "AZ123.4 EL45.0\n");
}

TEST(EasyComm, ParsesSetLines) {
  auto hamlib = parse_easycomm("AZ200.0 EL30.0");
  ASSERT_TRUE(hamlib.ok());
  ASSERT_EQ(hamlib->tokens.size(), 2u);
  EXPECT_EQ(hamlib->tokens[0].op, EasyCommOp::SetAz);
  EXPECT_DOUBLE_EQ(hamlib->tokens[0].angle_deg, 200.0);
  EXPECT_EQ(hamlib->tokens[1].op, EasyCommOp::SetEl);
  EXPECT_DOUBLE_EQ(hamlib->tokens[1].angle_deg, 30.0);
  // Seed 003: Nova and WISP send "AZxxx.x ELxx.x".
  auto nova = parse_easycomm("AZ012.5 EL07.3", EasyCommVersion::One);
  ASSERT_TRUE(nova.ok());
  EXPECT_DOUBLE_EQ(nova->tokens[0].angle_deg, 12.5);
  EXPECT_DOUBLE_EQ(nova->tokens[1].angle_deg, 7.3);
}

TEST(EasyComm, EasyCommOneFullLine) {
  auto line = parse_easycomm("AZ123.4 EL45.6 UP000 XXX DN000 XXX", EasyCommVersion::One);
  ASSERT_TRUE(line.ok()) << line.error().message;
  ASSERT_EQ(line->tokens.size(), 4u);
  EXPECT_EQ(line->tokens[2].op, EasyCommOp::UplinkFreq);
  EXPECT_EQ(line->tokens[2].text, "XXX");
  EXPECT_EQ(line->tokens[3].op, EasyCommOp::DownlinkFreq);
  auto full = parse_easycomm("AZ1.0 EL2.0 UP435100000 FM DN145900000 USB", EasyCommVersion::One);
  ASSERT_TRUE(full.ok());
  EXPECT_EQ(full->tokens[2].freq_hz, 435100000u);
  EXPECT_EQ(full->tokens[3].text, "USB");
  EXPECT_EQ(format_easycomm_reply(*full, kAt), "");
  // EasyComm I has no queries or motion commands.
  EXPECT_FALSE(parse_easycomm("AZ EL", EasyCommVersion::One).ok());
  EXPECT_FALSE(parse_easycomm("SA SE", EasyCommVersion::One).ok());
}

TEST(EasyComm, OtherCommands) {
  auto line = parse_easycomm("ML MR MU MD AO LO UMFM DRIC910");
  ASSERT_TRUE(line.ok());
  EXPECT_EQ(line->tokens[0].op, EasyCommOp::MoveLeft);
  EXPECT_EQ(line->tokens[7].text, "IC910");
  EXPECT_EQ(parse_easycomm("PARK")->tokens[0].op, EasyCommOp::Park);
  EXPECT_EQ(parse_easycomm("RESET")->tokens[0].op, EasyCommOp::Reset);
  EXPECT_TRUE(parse_easycomm("")->tokens.empty());
  EXPECT_TRUE(parse_easycomm("   ")->tokens.empty());
}

TEST(EasyComm, Rejects) {
  const std::vector<std::string_view> bad = {"AZnan",
                                             "AZinf",
                                             "AZ1e2",
                                             "AZ12.3.4",
                                             "AZ.",
                                             "AZ12x",
                                             "AZ-",
                                             "EL+",
                                             "AZ 1 2",
                                             "XX",
                                             "az",
                                             "AZ500.0",
                                             "EL-1.0",
                                             "EL180.1",
                                             "SAX",
                                             "VE1",
                                             "UPabc",
                                             "UP",
                                             "UP1234567890123",
                                             "PARKING",
                                             "AZ1 AZ2 AZ3 AZ4 AZ5 AZ6 AZ7 AZ8 AZ9",
                                             "UM!",
                                             "AZ\t1",
                                             "AZ12,5"};
  for (auto line : bad) EXPECT_FALSE(parse_easycomm(line).ok()) << "'" << line << "'";
  EXPECT_FALSE(parse_easycomm(std::string(200, 'A')).ok());
  TargetLimits wide{-180.0, 540.0, -10.0, 190.0};
  EXPECT_TRUE(parse_easycomm("AZ-170.0 EL-5.5", EasyCommVersion::Two, wide).ok());
}

TEST(EasyComm, FormatsAngles) {
  EXPECT_EQ(format_easycomm_angle("AZ", -0.04), "AZ0.0");
  EXPECT_EQ(format_easycomm_angle("EL", -4.96), "EL-5.0");
  EXPECT_EQ(format_easycomm_angle("AZ", 359.96), "AZ360.0");
  EXPECT_EQ(format_easycomm_angle("AZ", std::nan("")), "");
  EXPECT_EQ(serve("AZ\n", {359.97, 0.0}), "AZ0.0\n");
  EXPECT_EQ(serve("AZ\n", {420.0, 0.0}), "AZ60.0\n");
  EXPECT_EQ(serve("AZ\n", {420.0, 0.0}, EasyCommVersion::Two, {false, false}), "AZ420.0\n");
  EXPECT_EQ(serve("AZ EL\n", {std::nan(""), 1.0}), "EL1.0\n");
}

TEST(EasyComm, OverlongGarbageIsDroppedAndCounted) {
  BoundedLineAssembler assembler = make_easycomm_assembler();
  for (int i = 0; i < 5000; ++i) EXPECT_FALSE(assembler.push('Q'));
  EXPECT_LE(assembler.pending_chars(), kEasyCommMaxLineChars);
  EXPECT_FALSE(assembler.push('\n'));
  EXPECT_EQ(assembler.overlong_lines(), 1u);
  EXPECT_EQ(serve(std::string(5000, 'Q') + "\nAZ\n", kAt), "AZ123.4\n");
}

TEST(EasyComm, SeededRandomBytesNeverCrash) {
  std::mt19937_64 rng(0xEA5C'0BAD);
  const std::string_view alphabet = "AZELUPDNSMRVGO0123456789.-+ \x01naif";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  std::uniform_int_distribution<std::size_t> len(0, 140);
  for (int i = 0; i < 5000; ++i) {
    std::string line(len(rng), ' ');
    for (char& c : line) c = alphabet[pick(rng)];
    auto parsed = parse_easycomm(line);
    if (!parsed) continue;
    EXPECT_LE(parsed->tokens.size(), kEasyCommMaxTokens);
    for (const auto& token : parsed->tokens) EXPECT_TRUE(std::isfinite(token.angle_deg));
    (void)format_easycomm_reply(*parsed, kAt);
  }
}

TEST(EasyComm, SeededRoundTrip) {
  std::mt19937_64 rng(0xEA5C'0002);
  std::uniform_int_distribution<int> az_tenths(0, 3599);
  std::uniform_int_distribution<int> el_tenths(0, 1800);
  for (int i = 0; i < 2000; ++i) {
    const double az = az_tenths(rng) / 10.0;
    const double el = el_tenths(rng) / 10.0;
    // Server reply -> the set line a client would send back -> parse: the same angles.
    const std::string reply = format_easycomm_reply(*parse_easycomm("AZ EL"), {az, el});
    ASSERT_EQ(reply.back(), '\n');
    auto line = parse_easycomm(std::string_view(reply).substr(0, reply.size() - 1));
    ASSERT_TRUE(line.ok()) << reply;
    ASSERT_EQ(line->tokens.size(), 2u);
    EXPECT_NEAR(line->tokens[0].angle_deg, az, 1e-9);
    EXPECT_NEAR(line->tokens[1].angle_deg, el, 1e-9);
  }
}

}  // namespace
}  // namespace azt::proto
