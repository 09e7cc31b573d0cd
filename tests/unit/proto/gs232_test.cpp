// GS-232A/B server codec: byte transcripts from reference/rotator-controllers-and-protocols.md §8.2
// (server test vectors), rejection cases and seeded round trips.
#include "azt/proto/gs232.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace azt::proto {
namespace {

// Feeds `bytes` through the assembler and answers every complete line, as a server would.
std::string serve(std::string_view bytes, double az_deg, double el_deg,
                  const Gs232ReplyOptions& options) {
  BoundedLineAssembler assembler = make_gs232_assembler();
  std::string out;
  for (char c : bytes) {
    auto line = assembler.push(c);
    if (!line) continue;
    auto cmd = parse_gs232(*line);
    out += cmd ? format_gs232_reply(*cmd, az_deg, el_deg, options) : format_gs232_error();
  }
  return out;
}

constexpr Gs232ReplyOptions kB{Gs232Variant::B};
constexpr Gs232ReplyOptions kA{Gs232Variant::A};

TEST(Gs232, BModeTranscripts) {
  EXPECT_EQ(serve("C2\r", 123.0, 45.0, kB), "AZ=123  EL=045\r\n");
  EXPECT_EQ(serve("C\r", 123.0, 45.0, kB), "AZ=123\r\n");
  EXPECT_EQ(serve("B\r", 123.0, 45.0, kB), "EL=045\r\n");
  EXPECT_EQ(serve("S\r", 123.0, 45.0, kB), "\r");
  EXPECT_EQ(serve("Q\r", 123.0, 45.0, kB), "?>\r\n");
  // Hamlib >= 4.0 sends an extra CR after W: at most one CR back, never "?>".
  EXPECT_EQ(serve("W123 045\r\r", 0.0, 0.0, kB), "\r");
}

TEST(Gs232, AModeTranscripts) {
  EXPECT_EQ(serve("C2\r", 123.0, 45.0, kA), "+0123+0045\r\n");
  EXPECT_EQ(serve("C\r", 123.0, 45.0, kA), "+0123\r\n");
  EXPECT_EQ(serve("B\r", 123.0, 45.0, kA), "+0045\r\n");
  EXPECT_EQ(serve("C2\r", 7.0, -3.0, kA), "+0007-0003\r\n");
}

TEST(Gs232, K3ngSeparatorAndRawOverlap) {
  Gs232ReplyOptions k3ng{Gs232Variant::B, "", false};
  EXPECT_EQ(serve("C2\r", 322.0, 0.0, k3ng), "AZ=322EL=000\r\n");
  EXPECT_EQ(serve("C\r", 420.0, 0.0, k3ng), "AZ=420\r\n");
  EXPECT_EQ(serve("C\r", 420.0, 0.0, kB), "AZ=060\r\n");
  EXPECT_EQ(serve("C\r", 359.6, 0.0, kB), "AZ=000\r\n");
}

TEST(Gs232, CrLfIsOneTerminatorAndEmptyLinesAreSilent) {
  EXPECT_EQ(serve("C2\r\n", 1.0, 2.0, kB), "AZ=001  EL=002\r\n");
  EXPECT_EQ(serve("\r\r\n\r", 1.0, 2.0, kB), "");
  EXPECT_EQ(serve("c2\rw010 020\r", 1.0, 2.0, kA), "+0001+0002\r\n\r");
}

TEST(Gs232, ParsesCommands) {
  EXPECT_EQ(*parse_gs232("W123 045"), (Gs232Command{Gs232Op::GotoAzEl, 123, 45, 0}));
  EXPECT_EQ(*parse_gs232("M450"), (Gs232Command{Gs232Op::GotoAz, 450, 0, 0}));
  EXPECT_EQ(*parse_gs232("x3"), (Gs232Command{Gs232Op::SetSpeed, 0, 0, 3}));
  EXPECT_EQ(parse_gs232("O2")->op, Gs232Op::CalElOffset);
  EXPECT_EQ(parse_gs232("F")->op, Gs232Op::CalAzFull);
  EXPECT_EQ(parse_gs232("P45")->op, Gs232Op::Mode450);
  EXPECT_EQ(parse_gs232("H2")->op, Gs232Op::HelpEl);
  EXPECT_EQ(parse_gs232("S\r")->op, Gs232Op::StopAll);  // stray CR tolerated
  EXPECT_EQ(parse_gs232("")->op, Gs232Op::Empty);
}

TEST(Gs232, RejectsJunkAndOutOfRange) {
  const std::vector<std::string_view> bad = {
      "C3",       "C2 ",     "SS",        "X0",        "X5",           "X",        "W123 45",
      "W12 045",  "W123045", "W123  045", "W123 045 ", "W451 000",     "W123 181", "M",
      "M12",      "M1234",   "M-12",      "M+12",      "M12.5",        "Wnan 000", "Winf inf",
      "W123 04x", "P",       "P90",       "?",         "M010 020 030", "Q",        "\x01"};
  for (auto line : bad) EXPECT_FALSE(parse_gs232(line).ok()) << "'" << line << "'";
  EXPECT_FALSE(parse_gs232(std::string(100, 'C')).ok());
  TargetLimits narrow{0.0, 360.0, 0.0, 90.0};
  EXPECT_FALSE(parse_gs232("W361 000", narrow).ok());
  EXPECT_FALSE(parse_gs232("W100 091", narrow).ok());
  EXPECT_TRUE(parse_gs232("W360 090", narrow).ok());
}

TEST(Gs232, NonFinitePositionAnswersError) {
  EXPECT_EQ(serve("C2\r", std::nan(""), 0.0, kB), "?>\r\n");
}

TEST(Gs232, OverlongGarbageIsDroppedAndCounted) {
  BoundedLineAssembler assembler = make_gs232_assembler();
  std::string junk(1000, 'Z');
  for (char c : junk) EXPECT_FALSE(assembler.push(c));
  EXPECT_LE(assembler.pending_chars(), kGs232MaxLineChars);
  EXPECT_FALSE(assembler.push('\r'));  // the tail of the garbage ends here
  EXPECT_EQ(assembler.overlong_lines(), 1u);
  for (char c : std::string_view("C2")) EXPECT_FALSE(assembler.push(c));
  EXPECT_EQ(assembler.push('\r'), std::optional<std::string>("C2"));
}

TEST(Gs232, SeededRandomBytesNeverCrashAndAlwaysAnswer) {
  std::mt19937_64 rng(0x6232'0BAD);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<std::size_t> len(0, 80);
  for (int i = 0; i < 5000; ++i) {
    std::string line(len(rng), '\0');
    for (char& c : line) c = static_cast<char>(byte(rng));
    auto cmd = parse_gs232(line);
    const std::string reply = cmd ? format_gs232_reply(*cmd, 10.0, 20.0) : format_gs232_error();
    if (!cmd || cmd->op != Gs232Op::Empty) {
      EXPECT_FALSE(reply.empty()) << i;
    }
  }
}

TEST(Gs232, SeededRoundTrip) {
  std::mt19937_64 rng(0x6532'3332);
  std::uniform_int_distribution<int> az_dist(0, 450);
  std::uniform_int_distribution<int> el_dist(0, 180);
  for (int i = 0; i < 2000; ++i) {
    const int az = az_dist(rng);
    const int el = el_dist(rng);
    // What Hamlib sends: "W%03u %03u".
    std::string line = "W";
    line += std::to_string(az + 1000).substr(1) + " " + std::to_string(el + 1000).substr(1);
    auto cmd = parse_gs232(line);
    ASSERT_TRUE(cmd.ok()) << line;
    EXPECT_EQ(cmd->az_deg, az);
    EXPECT_EQ(cmd->el_deg, el);
    // And what it reads back: B "AZ=%d EL=%d" with raw overlap, A "+0%d+0%d".
    const std::string b =
        format_gs232_reply({Gs232Op::QueryAzEl}, az, el, {Gs232Variant::B, "  ", false});
    ASSERT_GE(b.size(), 10u);
    EXPECT_EQ(b, "AZ=" + line.substr(1, 3) + "  EL=" + line.substr(5, 3) + "\r\n");
    const std::string a =
        format_gs232_reply({Gs232Op::QueryAzEl}, az, el, {Gs232Variant::A, "", false});
    EXPECT_EQ(a, "+0" + line.substr(1, 3) + "+0" + line.substr(5, 3) + "\r\n");
  }
}

}  // namespace
}  // namespace azt::proto
