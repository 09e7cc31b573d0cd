// libFuzzer target for the EasyComm I/II session (make_easycomm_session: the CR/LF-framed
// BoundedLineAssembler + parse_easycomm + a RotatorService), reliability notes R24.
//
// Input: byte 0 is where to cut the payload for the split feed, bytes 1-2 pick the station and
// the version (fuzz_service.hpp Setup; the variant bit chooses EasyComm II over I), the rest is
// what the client sends. The payload is fed at once, in two pieces cut at byte 0, and one line
// at a time. Invariants:
// - all three give the same replies and the same calls of the service;
// - every target is finite and inside the session's TargetLimits; moves are unit steps;
// - per line: activity() exactly once, first (overlong lines included); at most one stop, one
//   target, one move and one park, in that order; a line that parse_easycomm refuses asks
//   nothing and gets nothing; a line without queries gets nothing; a reply is one line, printable,
//   ending in a single LF; EasyComm I never replies (it has no queries); while the position is
//   unknown no AZ/EL angle is reported;
// - replies are bounded: at most kMaxReplyPerLine per line, kReplyBytesPerInputByte per byte.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "azt/proto/easycomm.hpp"
#include "azt/proto/sessions.hpp"
#include "fuzz_service.hpp"
#include "fuzz_support.hpp"

namespace {

namespace proto = azt::proto;
namespace fuzz = azt::fuzz;
using fuzz::Call;
using fuzz::CallKind;

/// Eight VE queries with a 22-byte info line; angles are at most 1e9 (13 characters).
constexpr std::size_t kMaxReplyPerLine = 256;
/// "VE VE VE VE VE VE VE VE\n" answers 8 x 25 bytes for 24.
constexpr std::size_t kReplyBytesPerInputByte = 16;

bool is_line_end(char c) { return c == '\r' || c == '\n'; }

/// Requests in the order the session makes them (sessions.hpp): stop, target, move, park.
int request_rank(CallKind kind) {
  switch (kind) {
    case CallKind::Stop:
      return 1;
    case CallKind::GotoPosition:
    case CallKind::GotoAxis:
      return 2;
    case CallKind::Move:
      return 3;
    case CallKind::Park:
      return 4;
    default:
      return 0;
  }
}

bool has_query(const proto::EasyCommLine& line) {
  for (const auto& token : line.tokens) {
    if (token.op == proto::EasyCommOp::QueryAz || token.op == proto::EasyCommOp::QueryEl ||
        token.op == proto::EasyCommOp::Version || token.op == proto::EasyCommOp::Status ||
        token.op == proto::EasyCommOp::Errors) {
      return true;
    }
  }
  return false;
}

/// No "AZ"/"EL" field (VE's info text is lower case, so it cannot start one).
bool reports_no_angle(std::string_view reply) {
  std::size_t start = 0;
  while (start < reply.size()) {
    const auto end = reply.find(' ', start);
    const std::string_view field = reply.substr(start, end - start);
    if (field.starts_with("AZ") || field.starts_with("EL")) return false;
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return true;
}

struct Session {
  proto::EasyCommVersion version;
  proto::TargetLimits limits;
};

void check_requests(std::span<const Call> calls) {
  int rank = 0;
  for (const Call& call : calls) {
    AZT_FUZZ_REQUIRE(call.kind != CallKind::Activity);
    const int next = request_rank(call.kind);
    if (next == 0) continue;
    AZT_FUZZ_REQUIRE(next > rank);  // at most one of each, in order
    rank = next;
  }
}

/// One piece ending in CR or LF (or the unterminated rest) fed alone.
void check_line(std::string_view piece, std::string_view reply, std::span<const Call> calls,
                const fuzz::FuzzRotatorService& service, const Session& session) {
  if (piece.empty() || !is_line_end(piece.back())) {
    AZT_FUZZ_REQUIRE(reply.empty() && calls.empty());
    return;
  }
  AZT_FUZZ_REQUIRE(!calls.empty() && calls.front().kind == CallKind::Activity);
  check_requests(calls.subspan(1));
  AZT_FUZZ_REQUIRE(reply.size() <= kMaxReplyPerLine);
  const std::string_view line = piece.substr(0, piece.size() - 1);
  const auto parsed = proto::parse_easycomm(line, session.version, session.limits);
  if (!parsed || !has_query(*parsed)) {
    AZT_FUZZ_REQUIRE(reply.empty());
    if (!parsed) AZT_FUZZ_REQUIRE(calls.size() == 1);
    return;
  }
  AZT_FUZZ_REQUIRE(session.version == proto::EasyCommVersion::Two);
  if (reply.empty()) return;  // only non-finite angles asked for: nothing to report
  AZT_FUZZ_REQUIRE(reply.back() == '\n');
  for (const char c : reply.substr(0, reply.size() - 1)) AZT_FUZZ_REQUIRE(fuzz::is_printable(c));
  if (!service.report()) AZT_FUZZ_REQUIRE(reports_no_angle(reply));
}

fuzz::Transcript run(const fuzz::Setup& setup, const std::vector<std::string_view>& pieces,
                     bool line_checks) {
  const Session config{setup.variant() ? proto::EasyCommVersion::Two : proto::EasyCommVersion::One,
                       setup.limits()};
  auto service = setup.make_service();
  const auto session = proto::make_easycomm_session(service, std::string(fuzz::kClient),
                                                    config.version, config.limits);
  fuzz::Transcript out;
  for (const std::string_view piece : pieces) {
    const std::size_t calls_before = service.calls().size();
    const std::string reply = fuzz::feed_checked(*session, service, piece);
    if (line_checks) {
      check_line(piece, reply, std::span<const Call>(service.calls()).subspan(calls_before),
                 service, config);
    }
    out.replies += reply;
  }
  AZT_FUZZ_REQUIRE(!session->finished());
  out.calls = service.calls();
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::SessionInput in = fuzz::read_session_input(data, size);
  const fuzz::Setup& setup = in.setup;
  const std::string_view payload = in.payload;
  const fuzz::Transcript whole = fuzz::same_however_fed(run, in, is_line_end);

  if (!setup.variant()) AZT_FUZZ_REQUIRE(whole.replies.empty());
  AZT_FUZZ_REQUIRE(whole.replies.empty() || whole.replies.back() == '\n');
  for (const char c : whole.replies) AZT_FUZZ_REQUIRE(fuzz::is_printable(c) || c == '\n');
  AZT_FUZZ_REQUIRE(whole.replies.size() <= kReplyBytesPerInputByte * payload.size());
  std::size_t line_ends = 0;
  for (const char c : payload) line_ends += is_line_end(c) ? 1U : 0U;
  const std::size_t activities = fuzz::count_calls(whole.calls, CallKind::Activity);
  AZT_FUZZ_REQUIRE(activities == line_ends);  // every line, even empty or overlong, is traffic
  AZT_FUZZ_REQUIRE(whole.replies.size() <= kMaxReplyPerLine * activities);
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) {
  return azt::fuzz::replay_files("easycomm_session_fuzz", argc, argv);
}
#endif
