// libFuzzer target for the GS-232A/B session (make_gs232_session: the CR-framed
// BoundedLineAssembler + parse_gs232 + a RotatorService), reliability notes R24.
//
// Input: byte 0 is where to cut the payload for the split feed, bytes 1-2 pick the station and
// the variant (fuzz_service.hpp Setup; the variant bit chooses A or B), the rest is what the
// client sends. The payload is fed at once, in two pieces cut at byte 0, and one CR-ended line at
// a time. Invariants:
// - all three give the same replies and the same calls of the service;
// - every target is finite, a whole number of degrees (three digits) and inside the session's
//   TargetLimits; every move is a unit step on one axis;
// - per line: activity() exactly once, first, at most one request; an empty line (LFs are
//   ignored) gets no reply, any other exactly one reply holding one CR, at its end or followed by
//   LF; an overlong line gets "?>\r\n" and nothing else; a request the station refuses, or a
//   query while the position is unknown, gets "?>\r\n"; besides CR/LF replies are printable;
// - A-variant position replies are "+0aaa"-style fields; B-variant ones start "AZ=" or "EL=";
// - replies are bounded: at most kMaxReplyPerLine per line, kReplyBytesPerInputByte per byte.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "azt/proto/gs232.hpp"
#include "azt/proto/sessions.hpp"
#include "fuzz_service.hpp"
#include "fuzz_support.hpp"

namespace {

namespace proto = azt::proto;
namespace fuzz = azt::fuzz;
using fuzz::Call;
using fuzz::CallKind;

/// The help text (56 bytes) is the longest reply; positions are at most 1e6 (7 digits).
constexpr std::size_t kMaxReplyPerLine = 64;
/// "H\r" answers 56 bytes for 2.
constexpr std::size_t kReplyBytesPerInputByte = 32;
constexpr std::string_view kError = "?>\r\n";

bool is_cr(char c) { return c == '\r'; }

bool is_whole_target(double deg) { return deg >= 0.0 && deg <= 999.0 && deg == std::floor(deg); }

/// One reply: one CR, at the end or before a final LF; printable before it.
void check_reply_shape(std::string_view reply) {
  AZT_FUZZ_REQUIRE(!reply.empty() && reply.size() <= kMaxReplyPerLine);
  std::string_view body = reply;
  if (body.back() == '\n') body.remove_suffix(1);
  AZT_FUZZ_REQUIRE(!body.empty() && body.back() == '\r');
  body.remove_suffix(1);
  for (const char c : body) AZT_FUZZ_REQUIRE(fuzz::is_printable(c));
}

void check_position_reply(std::string_view reply, proto::Gs232Variant variant) {
  if (reply == kError) return;
  if (variant == proto::Gs232Variant::A) {
    AZT_FUZZ_REQUIRE(reply.front() == '+' || reply.front() == '-');
    for (const char c : reply.substr(0, reply.size() - 2)) {
      AZT_FUZZ_REQUIRE(c == '+' || c == '-' || (c >= '0' && c <= '9'));
    }
  } else {
    AZT_FUZZ_REQUIRE(reply.substr(0, 3) == "AZ=" || reply.substr(0, 3) == "EL=");
  }
}

/// One piece ending in CR (or the unterminated rest) fed alone.
void check_line(std::string_view piece, std::string_view reply, std::span<const Call> calls,
                const fuzz::FuzzRotatorService& service, proto::Gs232Variant variant) {
  if (piece.empty() || !is_cr(piece.back())) {
    AZT_FUZZ_REQUIRE(reply.empty() && calls.empty());
    return;
  }
  AZT_FUZZ_REQUIRE(!calls.empty() && calls.front().kind == CallKind::Activity);
  std::string line;  // what the controller sees: LF is ignored wherever it is
  for (const char c : piece.substr(0, piece.size() - 1)) {
    if (c != '\n') line.push_back(c);
  }
  if (line.empty()) {
    AZT_FUZZ_REQUIRE(reply.empty() && calls.size() == 1);
    return;
  }
  check_reply_shape(reply);
  if (line.size() > proto::kGs232MaxLineChars) {
    AZT_FUZZ_REQUIRE(reply == kError && calls.size() == 1);
    return;
  }
  std::size_t requests = 0;
  bool queried = false;
  for (const Call& call : calls.subspan(1)) {
    AZT_FUZZ_REQUIRE(call.kind != CallKind::Activity && call.kind != CallKind::Info &&
                     call.kind != CallKind::Park);
    queried = queried || call.kind == CallKind::Position;
    requests += call.kind != CallKind::Position ? 1U : 0U;
  }
  AZT_FUZZ_REQUIRE(requests <= 1 && !(queried && requests == 1));
  const CallKind last = calls.back().kind;
  const bool refusable =
      last == CallKind::GotoPosition || last == CallKind::GotoAxis || last == CallKind::Move;
  if (refusable && service.status() != proto::ServiceStatus::Ok) {
    AZT_FUZZ_REQUIRE(reply == kError);
  }
  if (requests == 1 && !(refusable && service.status() != proto::ServiceStatus::Ok)) {
    AZT_FUZZ_REQUIRE(reply == "\r");
  }
  if (queried) {
    if (!service.report()) AZT_FUZZ_REQUIRE(reply == kError);
    check_position_reply(reply, variant);
  }
}

fuzz::Transcript run(const fuzz::Setup& setup, const std::vector<std::string_view>& pieces,
                     bool line_checks) {
  const auto variant = setup.variant() ? proto::Gs232Variant::B : proto::Gs232Variant::A;
  auto service = setup.make_service();
  const auto session =
      proto::make_gs232_session(service, std::string(fuzz::kClient), variant, setup.limits());
  fuzz::Transcript out;
  for (const std::string_view piece : pieces) {
    const std::size_t calls_before = service.calls().size();
    const std::string reply = fuzz::feed_checked(*session, service, piece);
    if (line_checks) {
      check_line(piece, reply, std::span<const Call>(service.calls()).subspan(calls_before),
                 service, variant);
    }
    out.replies += reply;
  }
  AZT_FUZZ_REQUIRE(!session->finished());  // a serial line never ends the conversation
  out.calls = service.calls();
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::SessionInput in = fuzz::read_session_input(data, size);
  const std::string_view payload = in.payload;
  const fuzz::Transcript whole = fuzz::same_however_fed(run, in, is_cr);

  AZT_FUZZ_REQUIRE(whole.replies.empty() || whole.replies.back() == '\r' ||
                   whole.replies.ends_with("\r\n"));
  AZT_FUZZ_REQUIRE(whole.replies.size() <= kReplyBytesPerInputByte * payload.size());
  std::size_t line_ends = 0;
  for (const char c : payload) line_ends += is_cr(c) ? 1U : 0U;
  std::size_t activities = 0;
  for (const Call& call : whole.calls) {
    activities += call.kind == CallKind::Activity ? 1U : 0U;
    if (call.kind == CallKind::GotoPosition) {
      AZT_FUZZ_REQUIRE(is_whole_target(call.az_deg) && is_whole_target(call.el_deg));
    }
    if (call.kind == CallKind::GotoAxis) {
      AZT_FUZZ_REQUIRE(call.axis == proto::Axis::Az && is_whole_target(call.az_deg));
    }
    if (call.kind == CallKind::Move) AZT_FUZZ_REQUIRE(call.move_az == 0 || call.move_el == 0);
  }
  AZT_FUZZ_REQUIRE(activities == line_ends);  // every CR ends a line, even an empty one
  AZT_FUZZ_REQUIRE(whole.replies.size() <= kMaxReplyPerLine * activities);
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) {
  return azt::fuzz::replay_files("gs232_session_fuzz", argc, argv);
}
#endif
