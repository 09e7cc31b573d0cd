// Protocol sessions against a recording RotatorService: byte-exact transcripts (reply bytes from
// reference/rotator-controllers-and-protocols.md §8.1-§8.4 and the codec tests) and the exact
// requests each conversation makes of the station.
#include "azt/proto/sessions.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "azt/proto/rotctld.hpp"
#include "fake_rotator_service.hpp"

namespace azt::proto {
namespace {

using Calls = std::vector<std::string>;
using test::FakeRotatorService;

std::string bytes(std::initializer_list<std::uint8_t> values) {
  std::string out;
  for (const std::uint8_t value : values) out.push_back(static_cast<char>(value));
  return out;
}

// --- rotctld (§8.1) -----------------------------------------------------------------------------

struct RotctldFixture : ::testing::Test {
  FakeRotatorService service;
  std::unique_ptr<ProtocolSession> session = make_rotctld_session(service, "c1", TargetLimits{});
};

TEST_F(RotctldFixture, GpredictSetThenGetInOneFeed) {
  service.report = PositionReport{123.45, 10.0, 123.45};
  EXPECT_EQ(session->feed("P 123,45 10,00\np\n"), "RPRT 0\n123.45\n10.00\n");
  EXPECT_EQ(service.calls, (Calls{"activity c1", "goto_position c1 123.45 10", "activity c1"}));
  EXPECT_FALSE(session->finished());
}

TEST_F(RotctldFixture, MoveDirectionsMapToAxisSteps) {
  EXPECT_EQ(session->feed("M 8 50\nM 16 50\nM UP 1\nM 4 -1\nM UP_RIGHT -1\nM 128 100\n"),
            "RPRT 0\nRPRT 0\nRPRT 0\nRPRT 0\nRPRT 0\nRPRT 0\n");
  service.record_activity = false;
  EXPECT_EQ(session->feed("M 32 5\nM 256 5\n"), "RPRT 0\nRPRT 0\n");
  EXPECT_EQ(service.calls,
            (Calls{"activity c1", "move c1 -1 0", "activity c1", "move c1 1 0", "activity c1",
                   "move c1 0 1", "activity c1", "move c1 0 -1", "activity c1", "move c1 1 1",
                   "activity c1", "move c1 -1 -1", "move c1 -1 1", "move c1 1 -1"}));
}

TEST_F(RotctldFixture, StopParkResetInfoAndDumpState) {
  service.record_activity = false;
  service.info_text = "azeltrack\nline two";
  EXPECT_EQ(session->feed("S\nK\nR 1\n_\n"), "RPRT 0\nRPRT 0\nRPRT 0\nazeltrack line two\n");
  EXPECT_EQ(service.calls, (Calls{"stop c1 all", "park c1", "stop c1 all"}));
  auto narrow = make_rotctld_session(service, "c2", TargetLimits{0.0, 360.0, 0.0, 180.0});
  EXPECT_EQ(narrow->feed("\\dump_state\n"),
            "1\n1\nmin_az=0.000000\nmax_az=360.000000\nmin_el=0.000000\nmax_el=180.000000\n"
            "south_zero=0\nrot_type=AzEl\ndone\n");
  EXPECT_EQ(narrow->feed("P -10 0\n"), "RPRT -1\n");  // outside this session's limits
  EXPECT_EQ(service.calls.size(), 3U);
}

TEST_F(RotctldFixture, ServiceStatusBecomesRprtCode) {
  service.status = ServiceStatus::Rejected;
  EXPECT_EQ(session->feed("P 10 20\n"), "RPRT -9\n");
  EXPECT_EQ(session->feed("+P 10 20\n"), "set_pos: 10 20\nRPRT -9\n");
  service.status = ServiceStatus::Invalid;
  EXPECT_EQ(session->feed("K\n"), "RPRT -1\n");
  service.status = ServiceStatus::Unavailable;
  EXPECT_EQ(session->feed("M 2 50\n"), "RPRT -6\n");
  EXPECT_EQ(rprt_code(ServiceStatus::Ok), 0);
  EXPECT_EQ(rprt_code(ServiceStatus::Invalid), kRprtInvalid);
  EXPECT_EQ(rprt_code(ServiceStatus::Rejected), kRprtRejected);
  EXPECT_EQ(rprt_code(ServiceStatus::Unavailable), kRprtIo);
}

TEST_F(RotctldFixture, StalePositionAnswersRprtMinus6AndKeepsTheConnection) {
  service.report = std::nullopt;
  EXPECT_EQ(session->feed("p\n+p\n"), "RPRT -6\nget_pos:\nRPRT -6\n");
  EXPECT_FALSE(session->finished());
  EXPECT_EQ(service.position_queries, 2);
}

TEST_F(RotctldFixture, QuitFinishesAndLaterLinesAreIgnored) {
  service.report = PositionReport{1.0, 2.0, 1.0};
  EXPECT_EQ(session->feed("p\nq\nS\n"), "1.00\n2.00\n");
  EXPECT_TRUE(session->finished());
  EXPECT_EQ(service.calls, (Calls{"activity c1", "activity c1"}));  // no stop after q
  EXPECT_EQ(session->feed("S\n"), "");
}

TEST_F(RotctldFixture, ErrorsSplitLinesCommentsAndOverlongLines) {
  EXPECT_EQ(session->feed("P 500 0\nP nan 1\nZ\n"), "RPRT -1\nRPRT -1\nRPRT -4\n");
  EXPECT_EQ(session->feed("P 1"), "");
  EXPECT_EQ(session->feed("0 20\r\n# comment\n"), "RPRT 0\n");
  EXPECT_EQ(session->feed(std::string(300, 'x') + "\np\n"), "RPRT -1\n123.40\n45.60\n");
  EXPECT_EQ(service.calls,
            (Calls{"activity c1", "activity c1", "activity c1", "activity c1",
                   "goto_position c1 10 20", "activity c1", "activity c1", "activity c1"}));
}

// --- GS-232 (§8.2) ------------------------------------------------------------------------------

struct Gs232Fixture : ::testing::Test {
  FakeRotatorService service;
  std::unique_ptr<ProtocolSession> b =
      make_gs232_session(service, "g", Gs232Variant::B, TargetLimits{0.0, 450.0, 0.0, 90.0});
  void SetUp() override { service.report = PositionReport{123.0, 45.0, 123.0}; }
};

TEST_F(Gs232Fixture, HamlibGs232bSetAnswersOneCr) {
  EXPECT_EQ(b->feed("W123 045\r\r"), "\r");
  EXPECT_EQ(service.calls, (Calls{"activity g", "goto_position g 123 45", "activity g"}));
}

TEST_F(Gs232Fixture, QueriesInBothVariants) {
  EXPECT_EQ(b->feed("C2\r"), "AZ=123  EL=045\r\n");
  EXPECT_EQ(b->feed("C\rB\r"), "AZ=123\r\nEL=045\r\n");
  auto a = make_gs232_session(service, "g", Gs232Variant::A, TargetLimits{});
  EXPECT_EQ(a->feed("C2\r\n"), "+0123+0045\r\n");
  EXPECT_EQ(a->feed("c\r"), "+0123\r\n");
  EXPECT_EQ(service.position_queries, 5);
}

TEST_F(Gs232Fixture, MotionCommandsCallTheService) {
  service.record_activity = false;
  EXPECT_EQ(b->feed("M200\rS\rA\rE\rL\rR\rU\rD\rX2\rP45\r"), std::string(10, '\r'));
  EXPECT_EQ(service.calls, (Calls{"goto_axis g az 200", "stop g all", "stop g az", "stop g el",
                                  "move g -1 0", "move g 1 0", "move g 0 1", "move g 0 -1"}));
}

TEST_F(Gs232Fixture, ErrorsAnswerQuestionPrompt) {
  service.record_activity = false;
  EXPECT_EQ(b->feed("Q\rW123 095\r"), "?>\r\n?>\r\n");  // unknown; el outside 0..90
  service.status = ServiceStatus::Rejected;
  EXPECT_EQ(b->feed("W010 020\rR\r"), "?>\r\n?>\r\n");
  EXPECT_EQ(service.calls, (Calls{"goto_position g 10 20", "move g 1 0"}));
  service.report = std::nullopt;
  EXPECT_EQ(b->feed("C2\r"), "?>\r\n");
}

TEST_F(Gs232Fixture, OverlongLineAnswersOnceThenRecovers) {
  EXPECT_EQ(b->feed(std::string(100, 'C') + "\rC\r"), "?>\r\nAZ=123\r\n");
  EXPECT_EQ(service.calls, (Calls{"activity g", "activity g"}));
}

TEST_F(Gs232Fixture, WholeDegreeTargetsAreComparedAsDoubles) {
  auto session =
      make_gs232_session(service, "g", Gs232Variant::B, TargetLimits{0.0, 359.5, 0.0, 90.0});
  service.record_activity = false;
  EXPECT_EQ(session->feed("W360 000\rW359 000\r"), "?>\r\n\r");
  EXPECT_EQ(service.calls, (Calls{"goto_position g 359 0"}));
}

// --- EasyComm (§8.3) ----------------------------------------------------------------------------

struct EasyCommFixture : ::testing::Test {
  FakeRotatorService service;
  std::unique_ptr<ProtocolSession> two =
      make_easycomm_session(service, "e", EasyCommVersion::Two, TargetLimits{});
};

TEST_F(EasyCommFixture, QueriesAnsweredOnOneLine) {
  EXPECT_EQ(two->feed("AZ EL\n"), "AZ123.4 EL45.6\n");
  EXPECT_EQ(two->feed("AZ\r\nEL\r\n"), "AZ123.4\nEL45.6\n");
  service.info_text = "azeltrack 1.0\r\n";
  EXPECT_EQ(two->feed("VE\n"), "VEazeltrack 1.0\n");
}

TEST_F(EasyCommFixture, SetTokensOfOneLineAreOneRequest) {
  service.record_activity = false;
  EXPECT_EQ(two->feed("AZ200.0 EL30.0\n"), "");
  EXPECT_EQ(two->feed("AZ-10.5\nEL10\n"), "");  // az −10.5 is inside the −180..450 default
  EXPECT_EQ(two->feed("EL95.0\nAZnan\n"), "");  // rejected: nothing applied, nothing sent
  EXPECT_EQ(service.calls,
            (Calls{"goto_position e 200 30", "goto_axis e az -10.5", "goto_axis e el 10"}));
}

TEST_F(EasyCommFixture, MovesStopsAndPark) {
  service.record_activity = false;
  EXPECT_EQ(two->feed("ML MU\nMR\nMD\nSA SE \nSA\nSE\nPARK\nRESET\n"), "");
  EXPECT_EQ(service.calls, (Calls{"move e -1 1", "move e 1 0", "move e 0 -1", "stop e all",
                                  "stop e az", "stop e el", "park e", "stop e all"}));
}

TEST_F(EasyCommFixture, StatusBitsFollowThePosition) {
  EXPECT_EQ(two->feed("GS GE\n"), "GS1 GE0\n");
  service.report->moving = true;
  EXPECT_EQ(two->feed("GS\n"), "GS2\n");
  service.report->fault = true;
  EXPECT_EQ(two->feed("GS GE\n"), "GS8 GE1\n");
}

TEST_F(EasyCommFixture, UnknownPositionAnswersTheErrorStatus) {
  service.report = std::nullopt;
  EXPECT_EQ(two->feed("AZ EL\n"), "GS8 GE1\n");
  EXPECT_EQ(two->feed("AZ\n"), "GS8 GE1\n");
  EXPECT_EQ(two->feed("GS\n"), "GS8\n");
  EXPECT_EQ(two->feed("VE\n"), "VEazeltrack test station\n");
}

TEST_F(EasyCommFixture, EasyCommOneSetLine) {
  auto one = make_easycomm_session(service, "e", EasyCommVersion::One, TargetLimits{});
  service.record_activity = false;
  EXPECT_EQ(one->feed("AZ123.4 EL45.6 UP000 XXX DN000 XXX\r"), "");
  EXPECT_EQ(one->feed("AZ EL\r"), "");  // EasyComm I has no queries
  EXPECT_EQ(service.calls, (Calls{"goto_position e 123.4 45.6"}));
  EXPECT_EQ(service.position_queries, 0);
}

TEST_F(EasyCommFixture, ActivityForEveryLineEvenBadOnes) {
  EXPECT_EQ(two->feed("XX\nAZ\n"), "AZ123.4\n");
  EXPECT_EQ(service.calls, (Calls{"activity e", "activity e"}));
}

// Found by fuzz/easycomm_session_fuzz.cpp: an overlong line ended without any activity().
TEST_F(EasyCommFixture, OverlongLineIsActivityWithoutReply) {
  EXPECT_EQ(two->feed(std::string(kEasyCommMaxLineChars + 1, 'A') + "\nAZ\n"), "AZ123.4\n");
  EXPECT_EQ(service.calls, (Calls{"activity e", "activity e"}));
  EXPECT_EQ(two->feed(std::string(kEasyCommMaxLineChars + 5, 'A')), "");
  EXPECT_EQ(two->feed("\r\n"), "");  // CR ends the overlong line, LF is an empty line
  EXPECT_EQ(service.calls.size(), 4U);
}

// --- SPID (§8.4) --------------------------------------------------------------------------------

const std::string kStatusFrame = bytes({0x57, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x1F, 0x20});
const std::string kStopFrame = bytes({0x57, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x0F, 0x20});

struct SpidFixture : ::testing::Test {
  FakeRotatorService service;
  std::unique_ptr<ProtocolSession> rot2 = make_spid_session(service, "s", SpidConfig{});
  void SetUp() override { service.report = PositionReport{12.5, 34.0, 12.5}; }
};

TEST_F(SpidFixture, StatusRepliesWithTheReferenceFrame) {
  EXPECT_EQ(rot2->feed(kStatusFrame),
            bytes({0x57, 3, 7, 2, 5, 2, 3, 9, 4, 0, 2, 0x20}));  // az 12.5, el 34.0, PH = PV = 2
  EXPECT_EQ(service.calls, (Calls{"activity s"}));
}

TEST_F(SpidFixture, SetGetsNoReplyAndStopReplies) {
  service.record_activity = false;
  // §8.4 example: az 123.5, el 77.0, PH = PV = 2.
  const std::string set =
      bytes({0x57, 0x30, 0x39, 0x36, 0x37, 2, 0x30, 0x38, 0x37, 0x34, 2, 0x2F, 0x20});
  EXPECT_EQ(rot2->feed(set), "");
  EXPECT_EQ(rot2->feed(kStopFrame).size(), kSpidRot2ReplyBytes);
  EXPECT_EQ(service.calls, (Calls{"goto_position s 123.5 77", "stop s all"}));
}

TEST_F(SpidFixture, SplitFramesAndLeadingJunk) {
  EXPECT_EQ(rot2->feed("\x01\x02" + kStatusFrame.substr(0, 5)), "");
  EXPECT_EQ(rot2->feed(kStatusFrame.substr(5) + kStatusFrame).size(), 2 * kSpidRot2ReplyBytes);
}

TEST_F(SpidFixture, UnknownPositionGetsNoReply) {
  service.report = std::nullopt;
  EXPECT_EQ(rot2->feed(kStatusFrame + kStopFrame), "");
  EXPECT_EQ(service.calls, (Calls{"activity s", "activity s", "stop s all"}));
}

TEST_F(SpidFixture, Rot1ProgSetsAzimuthOnlyAndRepliesWithFiveBytes) {
  auto rot1 = make_spid_session(service, "s", SpidConfig{SpidDialect::Rot1Prog});
  service.report = PositionReport{100.0, 0.0, 100.0};
  service.record_activity = false;
  // H = 360 + az in H1..H3, H4 = '0' (§8.4): az 100.
  EXPECT_EQ(rot1->feed(bytes({0x57, '4', '6', '0', '0', 0, 0, 0, 0, 0, 0, 0x2F, 0x20})), "");
  EXPECT_EQ(rot1->feed(kStatusFrame), bytes({0x57, 4, 6, 0, 0x20}));
  EXPECT_EQ(service.calls, (Calls{"goto_axis s az 100"}));
}

}  // namespace
}  // namespace azt::proto
