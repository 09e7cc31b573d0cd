// libFuzzer target for the rotctld session (make_rotctld_session: LineAssembler +
// parse_rotctld_line + a RotatorService), reliability notes R24: a fuzz target for every parser.
//
// Input: byte 0 is where to cut the payload for the split feed, bytes 1-2 pick the station
// (fuzz_service.hpp Setup: position, status, limits, info; extra bit 0 a 1e300° position), the
// rest is what the client sends.
// The same payload is fed three ways: at once, in two pieces cut at byte 0, and one line at a
// time. Invariants:
// - all three give the same replies, the same calls of the service and the same finished();
// - every target is finite and inside the session's TargetLimits, every move is a unit step
//   (checked by the fake service as the request arrives);
// - replies are printable ASCII and '\n' only, at most kReplyBytesPerInputByte per input byte
//   (kHugeReplyBytesPerInputByte for a 1e300° position) and kMaxReplyPerLine per line;
// - line by line: an empty line gets nothing (no activity either); any other line calls
//   activity() exactly once, first, and makes at most one request; an overlong line is answered
//   "RPRT -1\n"; blank, comment and quit lines get no reply, every other line a reply ending in
//   '\n'; a request's status is the reply's final RPRT code (rprt_code);
// - after finished() nothing is answered and nothing is asked of the service.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "azt/proto/rotctld.hpp"
#include "azt/proto/sessions.hpp"
#include "fuzz_service.hpp"
#include "fuzz_support.hpp"

namespace {

namespace proto = azt::proto;
namespace fuzz = azt::fuzz;
using fuzz::Call;
using fuzz::CallKind;

/// A `+\dump_state` with five-digit limits is under 300 bytes; a `p` of 1e300 is two 300-digit
/// numbers. Both fit with room to spare.
constexpr std::size_t kMaxReplyPerLine = 1024;
/// The densest reply per byte sent is `+\dump_state\n` (about 20 bytes per byte), unless the
/// station reports a 300-digit angle: then "p\n" gets about 300 bytes per byte.
constexpr std::size_t kReplyBytesPerInputByte = 32;
constexpr std::size_t kHugeReplyBytesPerInputByte = 320;

/// Extra bit 0 overrides the position with finite but absurd angles, which rotctld (unlike the
/// serial protocols) prints in full, "%.2f" as Hamlib does.
bool huge_position(const fuzz::Setup& setup) { return setup.extra() % 2 == 1; }

bool is_line_end(char c) { return c == '\n' || c == '\r'; }
bool is_punct(char c) {
  return (c >= '!' && c <= '/') || (c >= ':' && c <= '@') || (c >= '[' && c <= '`') ||
         (c >= '{' && c <= '~');
}
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

/// The code of the reply's last record when it is "RPRT n" (records end in '\n', or in the ERP
/// prefix character, which is punctuation).
std::optional<int> final_rprt(std::string_view reply) {
  if (reply.empty() || reply.back() != '\n') return std::nullopt;
  reply.remove_suffix(1);
  const auto start = reply.rfind("RPRT ");
  if (start == std::string_view::npos) return std::nullopt;
  if (start > 0 && reply[start - 1] != '\n' && !is_punct(reply[start - 1])) return std::nullopt;
  std::string_view last = reply.substr(start + 5);
  const bool negative = !last.empty() && last.front() == '-';
  if (negative) last.remove_prefix(1);
  if (last.empty() || last.size() > 3) return std::nullopt;
  int code = 0;
  for (const char c : last) {
    if (c < '0' || c > '9') return std::nullopt;
    code = code * 10 + (c - '0');
  }
  return negative ? -code : code;
}

bool is_request(CallKind kind) {
  return kind == CallKind::GotoPosition || kind == CallKind::GotoAxis || kind == CallKind::Move ||
         kind == CallKind::Stop || kind == CallKind::Park;
}

/// One piece ending in CR or LF (or the unterminated rest) fed alone to a session that was not
/// finished before it.
void check_line(std::string_view piece, std::string_view reply, std::span<const Call> calls,
                bool finished_after, const fuzz::FuzzRotatorService& service) {
  AZT_FUZZ_REQUIRE(reply.size() <= kMaxReplyPerLine);
  if (piece.empty() || !is_line_end(piece.back()) || piece.size() == 1) {
    // An unfinished line waits; an empty line is not delivered at all.
    AZT_FUZZ_REQUIRE(reply.empty() && calls.empty() && !finished_after);
    return;
  }
  AZT_FUZZ_REQUIRE(!calls.empty() && calls.front().kind == CallKind::Activity);
  const std::string_view line = piece.substr(0, piece.size() - 1);
  std::size_t requests = 0;
  for (const Call& call : calls.subspan(1)) {
    AZT_FUZZ_REQUIRE(call.kind != CallKind::Activity);
    requests += is_request(call.kind) ? 1U : 0U;
  }
  AZT_FUZZ_REQUIRE(requests <= 1);
  if (line.size() > proto::LineAssembler::kDefaultMaxLineBytes) {
    AZT_FUZZ_REQUIRE(reply == "RPRT -1\n" && calls.size() == 1 && !finished_after);
    return;
  }
  const std::string_view text = trim(line);
  if (text.empty() || text.front() == '#' || finished_after) {
    AZT_FUZZ_REQUIRE(reply.empty() && calls.size() == 1);
    return;
  }
  AZT_FUZZ_REQUIRE(!reply.empty() && reply.back() == '\n');
  const Call& last = calls.back();
  if (requests == 1) {
    const int expected =
        last.kind == CallKind::Stop ? proto::kRprtOk : proto::rprt_code(service.status());
    AZT_FUZZ_REQUIRE(final_rprt(reply) == expected);
  }
}

/// Feeds `pieces` in order to a fresh session; with `line_checks` each piece is one line.
fuzz::Transcript run(const fuzz::Setup& setup, const std::vector<std::string_view>& pieces,
                     bool line_checks) {
  auto service = setup.make_service();
  if (huge_position(setup)) service.set_report(proto::PositionReport{1e300, -1e300, 1e300});
  const auto session =
      proto::make_rotctld_session(service, std::string(fuzz::kClient), setup.limits());
  fuzz::Transcript out;
  for (const std::string_view piece : pieces) {
    const bool finished_before = session->finished();
    const std::size_t calls_before = service.calls().size();
    const std::string reply = fuzz::feed_checked(*session, service, piece);
    if (line_checks && !finished_before) {
      check_line(piece, reply, std::span<const Call>(service.calls()).subspan(calls_before),
                 session->finished(), service);
    }
    out.replies += reply;
  }
  out.calls = service.calls();
  out.finished = session->finished();
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::SessionInput in = fuzz::read_session_input(data, size);
  const fuzz::Setup& setup = in.setup;
  const std::string_view payload = in.payload;
  const fuzz::Transcript whole = fuzz::same_however_fed(run, in, is_line_end);

  for (const char c : whole.replies) AZT_FUZZ_REQUIRE(fuzz::is_printable(c) || c == '\n');
  AZT_FUZZ_REQUIRE(whole.replies.empty() || whole.replies.back() == '\n');
  const std::size_t per_byte =
      huge_position(setup) ? kHugeReplyBytesPerInputByte : kReplyBytesPerInputByte;
  AZT_FUZZ_REQUIRE(whole.replies.size() <= per_byte * payload.size());
  std::size_t line_ends = 0;
  for (const char c : payload) line_ends += is_line_end(c) ? 1U : 0U;
  const std::size_t activities = fuzz::count_calls(whole.calls, CallKind::Activity);
  AZT_FUZZ_REQUIRE(activities <= line_ends);
  AZT_FUZZ_REQUIRE(whole.replies.size() <= kMaxReplyPerLine * activities);
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) {
  return azt::fuzz::replay_files("rotctld_session_fuzz", argc, argv);
}
#endif
