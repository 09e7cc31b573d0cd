// Hamlib rotctld codec. Expected bytes come from reference/rotator-controllers-and-protocols.md
// §8.1 (ERP examples and server test vectors) and from a capture of a real `rotctld -m 1 -T
// 127.0.0.1` (Hamlib 4.5.4, Debian 12 package libhamlib-utils, 2026-11-22), one TCP connection per
// command. Where this server deliberately differs from Hamlib (unknown commands, NaN, junk), the
// test says so.

#include "azt/proto/rotctld.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace {

using azt::proto::format_dump_state;
using azt::proto::format_error;
using azt::proto::format_get_info;
using azt::proto::format_get_pos;
using azt::proto::format_rprt;
using azt::proto::format_status;
using azt::proto::LineAssembler;
using azt::proto::LineStatus;
using azt::proto::MoveDirection;
using azt::proto::parse_rotctld_line;
using azt::proto::RotctldCommand;
using azt::proto::RotctldCommandKind;
using azt::proto::RotctldError;
using azt::proto::TargetLimits;

/// Hamlib's dummy rotator limits (reference §3: az −180…450, el 0…90).
const TargetLimits kDummyLimits{};

RotctldCommand parse_ok(std::string_view line, const TargetLimits& limits = kDummyLimits) {
  auto result = parse_rotctld_line(line, limits);
  if (const auto* error = std::get_if<RotctldError>(&result)) {
    ADD_FAILURE() << "'" << line << "' failed: " << error->message;
    return {};
  }
  return std::get<RotctldCommand>(result);
}

RotctldError parse_error(std::string_view line, const TargetLimits& limits = kDummyLimits) {
  auto result = parse_rotctld_line(line, limits);
  if (std::holds_alternative<RotctldCommand>(result)) {
    ADD_FAILURE() << "'" << line << "' parsed but should fail";
    return {};
  }
  return std::get<RotctldError>(result);
}

/// A minimal session: what a server would write for each line, with the rotator standing at
/// (az_deg, el_deg) and every command succeeding. Mirrors how apps/ will use the codec.
struct Session {
  LineAssembler lines;
  TargetLimits limits;
  double az_deg = 0.0;
  double el_deg = 0.0;
  bool closed = false;

  std::string answer(std::string_view line) {
    auto result = parse_rotctld_line(line, limits);
    if (const auto* error = std::get_if<RotctldError>(&result)) return format_error(*error);
    const auto& command = std::get<RotctldCommand>(result);
    switch (command.kind) {
      case RotctldCommandKind::GetPos:
        return format_get_pos(command, az_deg, el_deg);
      case RotctldCommandKind::GetInfo:
        return format_get_info(command, "Dummy rotator");
      case RotctldCommandKind::DumpState:
        return format_dump_state(command, limits);
      case RotctldCommandKind::Quit:
        closed = true;
        return {};
      case RotctldCommandKind::Ignore:
        return {};
      case RotctldCommandKind::SetPos:
        az_deg = command.az_deg;
        el_deg = command.el_deg;
        return format_status(command, 0);
      default:
        return format_status(command, 0);
    }
  }

  /// One read from the socket in, one write per answered line out.
  std::vector<std::string> read(std::string_view bytes) {
    std::vector<std::string> writes;
    lines.feed(bytes, [&](std::string_view line, LineStatus status) {
      std::string reply = status == LineStatus::Overlong
                              ? format_rprt(azt::proto::kRprtInvalid, {}, {})
                              : answer(line);
      if (!reply.empty()) writes.push_back(std::move(reply));
    });
    return writes;
  }

  std::string one(std::string_view bytes) {
    const auto writes = read(bytes);
    EXPECT_LE(writes.size(), 1U) << bytes;
    return writes.empty() ? std::string() : writes.front();
  }
};

// --- Worked examples: byte-exact replies --------------------------------------------------------

TEST(Rotctld, ServerTestVectorsFromReference) {
  Session s;
  EXPECT_EQ(s.one("p\n"), "0.00\n0.00\n");
  EXPECT_EQ(s.one("P 180 45\n"), "RPRT 0\n");
  EXPECT_EQ(s.one("P 180,5 45,25\n"), "RPRT 0\n");
  EXPECT_EQ(s.one("\\set_pos 180 45\n"), "RPRT 0\n");
  EXPECT_EQ(s.one("S\n"), "RPRT 0\n");
  EXPECT_EQ(s.one("K\n"), "RPRT 0\n");
  EXPECT_EQ(s.one("M 16 50\n"), "RPRT 0\n");
  EXPECT_EQ(s.one("R 1\n"), "RPRT 0\n");
  EXPECT_EQ(s.one("_\n"), "Dummy rotator\n");
  EXPECT_FALSE(s.closed);
  EXPECT_EQ(s.one("q\n"), "");
  EXPECT_TRUE(s.closed);
}

TEST(Rotctld, DumpStatePlainMatchesRotctlM1Capture) {
  Session s;
  EXPECT_EQ(s.one("\\dump_state\n"),
            "1\n1\nmin_az=-180.000000\nmax_az=450.000000\nmin_el=0.000000\nmax_el=90.000000\n"
            "south_zero=0\nrot_type=AzEl\ndone\n");
}

TEST(Rotctld, DumpStateReportsConfiguredLimits) {
  Session s;
  s.limits = TargetLimits{0.0, 360.0, -5.0, 180.0};
  EXPECT_EQ(s.one("\\dump_state\n"),
            "1\n1\nmin_az=0.000000\nmax_az=360.000000\nmin_el=-5.000000\nmax_el=180.000000\n"
            "south_zero=0\nrot_type=AzEl\ndone\n");
}

TEST(Rotctld, ExtendedExamplesFromReference) {
  Session s;
  EXPECT_EQ(s.one("+P 90 45\n"), "set_pos: 90 45\nRPRT 0\n");
  EXPECT_EQ(s.one("+\\get_pos\n"), "get_pos:\nAzimuth: 90.00\nElevation: 45.00\nRPRT 0\n");
  EXPECT_EQ(s.one(";\\get_pos\n"), "get_pos:;Azimuth: 90.00;Elevation: 45.00;RPRT 0\n");
  EXPECT_EQ(s.one("|\\set_pos 135 22.5\n"), "set_pos: 135 22.5|RPRT 0\n");
  EXPECT_EQ(s.one("+p\n"), "get_pos:\nAzimuth: 135.00\nElevation: 22.50\nRPRT 0\n");
  EXPECT_EQ(s.one("+\\dump_state\n"),
            "dump_state:\nrotctld Protocol Ver: 1\nRotor Model: 1\nMinimum Azimuth: -180.000000\n"
            "Maximum Azimuth: 450.000000\nMinimum Elevation: 0.000000\n"
            "Maximum Elevation: 90.000000\nSouth Zero: 0\nrot_type=AzEl\ndone\nRPRT 0\n");
}

TEST(Rotctld, ExtendedRepliesMatchRotctlM1Capture) {
  Session s;
  EXPECT_EQ(s.one("+_\n"), "get_info:\nInfo: Dummy rotator\nRPRT 0\n");
  EXPECT_EQ(s.one("+\\get_info\n"), "get_info:\nInfo: Dummy rotator\nRPRT 0\n");
  EXPECT_EQ(s.one("+S\n"), "stop:\nRPRT 0\n");
  EXPECT_EQ(s.one("+M 16 50\n"), "move: 16 50\nRPRT 0\n");
  EXPECT_EQ(s.one(";\\dump_state\n"),
            "dump_state:;rotctld Protocol Ver: 1;Rotor Model: 1;Minimum Azimuth: -180.000000;"
            "Maximum Azimuth: 450.000000;Minimum Elevation: 0.000000;"
            "Maximum Elevation: 90.000000;South Zero: 0;rot_type=AzEl;done;RPRT 0\n");
  // Out of range: Hamlib 4.5.4 echoes, then RPRT -1 (4.6 would say -21).
  EXPECT_EQ(s.one("+P 500 0\n"), "set_pos: 500 0\nRPRT -1\n");
}

TEST(Rotctld, GetPosIsTwoLinesInOneString) {
  Session s;
  s.az_deg = 14.371;
  s.el_deg = 14.366;
  const auto writes = s.read("p\n");
  ASSERT_EQ(writes.size(), 1U);
  EXPECT_EQ(writes[0], "14.37\n14.37\n");
}

TEST(Rotctld, GetPosMatchesPrintfTwoDecimals) {
  // "%.2f" is what Hamlib prints; the codec must agree byte for byte without using printf.
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> angle(-200.0, 470.0);
  const RotctldCommand get_pos = parse_ok("p");
  for (int i = 0; i < 2000; ++i) {
    const double az = angle(rng);
    const double el = angle(rng);
    char expected[128];
    std::snprintf(expected, sizeof expected, "%.2f\n%.2f\n", az, el);
    ASSERT_EQ(format_get_pos(get_pos, az, el), expected) << az << " " << el;
  }
  EXPECT_EQ(format_get_pos(get_pos, -0.001, 0.005), "-0.00\n0.01\n");
}

TEST(Rotctld, GetPosWithUnknownPositionIsAnError) {
  const RotctldCommand get_pos = parse_ok("p");
  EXPECT_EQ(format_get_pos(get_pos, std::nan(""), 0.0), "RPRT -6\n");
  EXPECT_EQ(format_get_pos(parse_ok("+p"), 1.0, std::numeric_limits<double>::infinity()),
            "get_pos:\nRPRT -6\n");
}

TEST(Rotctld, GetInfoKeepsTheReplyOnOneLine) {
  EXPECT_EQ(format_get_info(parse_ok("_"), "azeltrack\n0.1"), "azeltrack 0.1\n");
  // rotctl -m 2 shows 63 characters; a longer info is cut there, not by the client,
  // and never inside a UTF-8 sequence (the ° of "12°" below straddles character 63).
  const std::string long_info = "azeltrack 0.1.0 simulated antenna (12/12-bit encoders) at FN06HE";
  EXPECT_EQ(format_get_info(parse_ok("_"), long_info), long_info.substr(0, 63) + "\n");
  const std::string utf8 = std::string(62, 'x') + "\xC2\xB0 more";
  EXPECT_EQ(format_get_info(parse_ok("_"), utf8), std::string(62, 'x') + "\n");
}

// --- Parsing -----------------------------------------------------------------------------------

TEST(Rotctld, GpredictCommaDecimals) {
  const auto command = parse_ok("P 123,45 10,00");
  EXPECT_EQ(command.kind, RotctldCommandKind::SetPos);
  EXPECT_DOUBLE_EQ(command.az_deg, 123.45);
  EXPECT_DOUBLE_EQ(command.el_deg, 10.0);
  EXPECT_EQ(parse_ok("+P 123,45 10,00").echo, "set_pos: 123,45 10,00");
}

TEST(Rotctld, NetrotctlSixDecimals) {
  const auto command = parse_ok("P 359.123456 12.500000");
  EXPECT_DOUBLE_EQ(command.az_deg, 359.123456);
  EXPECT_DOUBLE_EQ(command.el_deg, 12.5);
}

TEST(Rotctld, ShortAndLongFormsAreTheSameCommand) {
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"P 10 20", "\\set_pos 10 20"}, {"p", "\\get_pos"},  {"S", "\\stop"},      {"K", "\\park"},
      {"M 8 -1", "\\move 8 -1"},      {"_", "\\get_info"}, {"R 1", "\\reset 1"},
  };
  for (const auto& [short_form, long_form] : pairs) {
    const auto a = parse_ok(short_form);
    const auto b = parse_ok(long_form);
    EXPECT_EQ(a.kind, b.kind) << short_form;
    EXPECT_EQ(a.echo, b.echo) << short_form;
    EXPECT_EQ(a.az_deg, b.az_deg);
    EXPECT_EQ(a.el_deg, b.el_deg);
  }
  EXPECT_EQ(parse_ok("\\dump_state").kind, RotctldCommandKind::DumpState);
  EXPECT_EQ(parse_ok("Q").kind, RotctldCommandKind::Quit);
}

TEST(Rotctld, MoveTakesNumbersOrKeywords) {
  auto command = parse_ok("\\move LEFT 50");
  EXPECT_EQ(command.direction, MoveDirection::Left);
  EXPECT_EQ(command.speed, 50);
  command = parse_ok("M CW -1");
  EXPECT_EQ(command.direction, MoveDirection::Right);
  EXPECT_EQ(command.speed, azt::proto::kMoveSpeedUnchanged);
  EXPECT_EQ(parse_ok("M 256 100").direction, MoveDirection::DownRight);
  EXPECT_EQ(parse_error("M 3 50").code, -1);
  EXPECT_EQ(parse_ok("M 16 0").speed, 0);  // Hamlib clients send 0; it is ignored
  EXPECT_EQ(parse_error("M 16 -2").code, -1);
  EXPECT_EQ(parse_error("M 16 101").code, -1);
  EXPECT_EQ(parse_error("M sideways 10").code, -1);
}

TEST(Rotctld, BlankAndCommentLinesNeedNoReply) {
  EXPECT_EQ(parse_ok("").kind, RotctldCommandKind::Ignore);
  EXPECT_EQ(parse_ok("   \t").kind, RotctldCommandKind::Ignore);
  EXPECT_EQ(parse_ok("# set by hand").kind, RotctldCommandKind::Ignore);
}

// --- Deliberate deviations: every line is answered ---------------------------------------------

TEST(Rotctld, UnknownCommandsAnswerRprtMinus4) {
  // Hamlib 4.5.4 sends nothing for "X" (captured); we answer ENIMPL.
  Session s;
  EXPECT_EQ(s.one("X\n"), "RPRT -4\n");
  EXPECT_EQ(s.one("\\set_frequency 1\n"), "RPRT -4\n");
  EXPECT_EQ(s.one("+\\get_posX\n"), "RPRT -4\n");
  EXPECT_EQ(s.one("V SPEED 10\n"), "RPRT -4\n");
  EXPECT_EQ(s.one("+\n"), "RPRT -4\n");
}

TEST(Rotctld, NonFiniteAndJunkAnswerRprtMinus1) {
  // Hamlib 4.5.4 answers "P nan 2" and "P 1 2 3" with RPRT 0 (captured); we refuse them.
  Session s;
  for (const char* line : {"P nan 2\n", "P 1 inf\n", "P -inf 0\n", "P 1 2 3\n", "P 1\n", "P\n",
                           "P 1x 2\n", "P 1,2,3 4\n", "P 0x10 4\n", "pX\n", "p 1\n", "S now\n",
                           "\\dump_state all\n", "R\n", "R one\n", "P 1e999 0\n"}) {
    EXPECT_EQ(s.one(line), "RPRT -1\n") << line;
  }
  EXPECT_EQ(s.one("+P nan 2\n"), "set_pos: nan 2\nRPRT -1\n");
  EXPECT_EQ(s.one(";p 1\n"), "get_pos: 1;RPRT -1\n");
}

// Found by fuzz/rotctld_session_fuzz.cpp: ",M \0" echoed the NUL byte in "move: \0,RPRT -1".
TEST(Rotctld, ExtendedEchoOfJunkIsPrintable) {
  Session s;
  EXPECT_EQ(s.one(std::string(",M \0\n", 5)), "move: ?,RPRT -1\n");
  EXPECT_EQ(s.one("+P 1\x1b[2J 2\n"), "set_pos: 1?[2J 2\nRPRT -1\n");
  EXPECT_EQ(s.one("+S \xc3\xa9\n"), "stop: ??\nRPRT -1\n");
}

TEST(Rotctld, OutOfRangeTargetsAnswerRprtMinus1) {
  Session s;
  EXPECT_EQ(s.one("P 500 0\n"), "RPRT -1\n");  // reference vector is -21 for Hamlib 4.6
  EXPECT_EQ(s.one("P -180.01 0\n"), "RPRT -1\n");
  EXPECT_EQ(s.one("P 0 -0.5\n"), "RPRT -1\n");
  EXPECT_EQ(s.one("P 0 90,01\n"), "RPRT -1\n");
  EXPECT_EQ(s.one("P -180 0\n"), "RPRT 0\n");  // limits are inclusive
  EXPECT_EQ(s.one("P 450 90\n"), "RPRT 0\n");
  EXPECT_DOUBLE_EQ(s.az_deg, 450.0);
}

TEST(Rotctld, FormatRprtCarriesAnyCode) {
  EXPECT_EQ(format_rprt(-9, {}, "set_pos: 1 2"), "RPRT -9\n");
  EXPECT_EQ(format_rprt(-9, {true, '\n'}, "set_pos: 1 2"), "set_pos: 1 2\nRPRT -9\n");
  EXPECT_EQ(format_status(parse_ok("|K"), -6), "park:|RPRT -6\n");
}

// --- Stream handling ---------------------------------------------------------------------------

TEST(Rotctld, PipelinedCommandsInOneRead) {
  Session s;
  const auto writes = s.read("\\dump_state\nP 10 20\np\nS\n");
  ASSERT_EQ(writes.size(), 4U);
  EXPECT_EQ(writes[1], "RPRT 0\n");
  EXPECT_EQ(writes[2], "10.00\n20.00\n");
  EXPECT_EQ(writes[3], "RPRT 0\n");
}

TEST(Rotctld, CommandSplitAcrossReads) {
  Session s;
  EXPECT_TRUE(s.read("P 12").empty());
  EXPECT_TRUE(s.read("3,4 5").empty());
  EXPECT_EQ(s.read(",6\r\n"), std::vector<std::string>{"RPRT 0\n"});
  EXPECT_DOUBLE_EQ(s.az_deg, 123.4);
  EXPECT_DOUBLE_EQ(s.el_deg, 5.6);
}

TEST(Rotctld, CrLfAndBareCrEndLines) {
  Session s;
  const auto writes = s.read("p\r\nS\rK\n\n\r\n");
  EXPECT_EQ(writes, (std::vector<std::string>{"0.00\n0.00\n", "RPRT 0\n", "RPRT 0\n"}));
  // A CRLF split between reads gives no empty extra reply.
  EXPECT_TRUE(s.read("S\r").size() == 1U);
  EXPECT_TRUE(s.read("\n").empty());
}

TEST(Rotctld, OverlongLineIsDroppedAndAnsweredOnce) {
  Session s;
  const std::string long_line = "P " + std::string(300, '1') + " 0\n";
  const auto writes = s.read(long_line + "p\n");
  EXPECT_EQ(writes, (std::vector<std::string>{"RPRT -1\n", "0.00\n0.00\n"}));
  EXPECT_EQ(s.lines.overlong_count(), 1U);
  EXPECT_EQ(s.lines.buffered_bytes(), 0U);
}

TEST(Rotctld, LineAssemblerBoundsItsBuffer) {
  LineAssembler lines(8);
  std::vector<std::string> seen;
  const auto collect = [&](std::string_view line, LineStatus status) {
    seen.push_back(status == LineStatus::Overlong ? "<overlong>" : std::string(line));
  };
  lines.feed("12345678\n123456789", collect);
  EXPECT_EQ(seen, (std::vector<std::string>{"12345678"}));
  EXPECT_EQ(lines.buffered_bytes(), 0U);  // the ninth byte started discarding
  lines.feed(std::string(10000, 'x'), collect);
  EXPECT_LE(lines.buffered_bytes(), 8U);
  lines.feed("\nok\n", collect);
  EXPECT_EQ(seen, (std::vector<std::string>{"12345678", "<overlong>", "ok"}));
  EXPECT_EQ(lines.overlong_count(), 1U);
  lines.feed("part", collect);
  lines.reset();
  lines.feed("ial\n", collect);
  EXPECT_EQ(seen.back(), "ial");
}

TEST(Rotctld, ParserRefusesOverlongInputWithoutAssembler) {
  EXPECT_EQ(parse_error("P " + std::string(400, '1') + " 0").code, -1);
}

TEST(Rotctld, RandomBytesAlwaysGetABoundedAnswer) {
  // Seeded garbage: the parser never throws, every non-blank line gets exactly one reply, and no
  // reply grows beyond the echo of a bounded line.
  std::mt19937 rng(4533);
  std::uniform_int_distribution<int> byte(0, 255);
  Session s;
  for (int i = 0; i < 2000; ++i) {
    std::string chunk;
    const int length = byte(rng) % 64;
    for (int j = 0; j < length; ++j) chunk += static_cast<char>(byte(rng));
    for (const auto& reply : s.read(chunk)) {
      EXPECT_FALSE(reply.empty());
      EXPECT_EQ(reply.back(), '\n');
      EXPECT_LT(reply.size(), 700U);
    }
  }
}

}  // namespace
