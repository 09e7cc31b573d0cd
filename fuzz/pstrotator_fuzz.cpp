// libFuzzer target for the PstRotator UDP codec (parse_pstrotator, handle_pstrotator_datagram),
// reliability notes R24.
//
// Input: byte 0 is where to cut the payload in two, bytes 1-2 pick the station (fuzz_service.hpp
// Setup), the rest is a datagram. The whole payload and its two halves are each handled as one
// datagram by a fresh service. Invariants per datagram:
// - activity() exactly once, first, even for a bad datagram; a datagram parse_pstrotator refuses
//   asks nothing else and gets no reply;
// - an accepted one makes exactly the requests its PstCommand names, in the order stop, target
//   (goto_position for both angles, goto_axis for one), park, every target finite and inside the
//   TargetLimits, and asks for the position only for AZ?/EL?;
// - the reply is "AZ:<number>\r" then "EL:<number>\r", each only if asked for and the position is
//   known and reportable, and each number reads back within 0.05 of the position;
// - parsing is blind to letter case and to white space around the datagram.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "azt/proto/pstrotator.hpp"
#include "azt/util/parse_number.hpp"
#include "fuzz_service.hpp"
#include "fuzz_support.hpp"

namespace {

namespace proto = azt::proto;
namespace fuzz = azt::fuzz;
using fuzz::Call;
using fuzz::CallKind;

/// "AZ:-1000000000.0\r" twice.
constexpr std::size_t kMaxReplyBytes = 34;

bool reportable(double deg) { return std::isfinite(deg) && std::fabs(deg) <= 1e9; }

/// Takes "NAME:<number>\r" from the front of `reply` when it is there; checks the number.
bool take_field(std::string_view& reply, std::string_view name, double expected_deg) {
  if (!reply.starts_with(name) || reply.substr(name.size(), 1) != ":") return false;
  const auto end = reply.find('\r');
  AZT_FUZZ_REQUIRE(end != std::string_view::npos);
  const auto value = azt::parse_finite_double(reply.substr(name.size() + 1, end - name.size() - 1));
  AZT_FUZZ_REQUIRE(value.has_value() && std::fabs(*value - expected_deg) <= 0.05 + 1e-6);
  reply.remove_prefix(end + 1);
  return true;
}

void check_reply(std::string_view reply, const proto::PstCommand& command,
                 const std::optional<proto::PositionReport>& position) {
  AZT_FUZZ_REQUIRE(reply.size() <= kMaxReplyBytes);
  if (!position) {
    AZT_FUZZ_REQUIRE(reply.empty());
    return;
  }
  const bool az = command.query_az && reportable(position->az_deg);
  const bool el = command.query_el && reportable(position->el_deg);
  AZT_FUZZ_REQUIRE(take_field(reply, "AZ", position->az_deg) == az);
  AZT_FUZZ_REQUIRE(take_field(reply, "EL", position->el_deg) == el);
  AZT_FUZZ_REQUIRE(reply.empty());
}

/// The requests an accepted datagram makes, after its activity().
void check_requests(std::span<const Call> calls, const proto::PstCommand& command) {
  std::size_t i = 0;
  const auto next = [&calls, &i](CallKind kind) {
    const bool match = i < calls.size() && calls[i].kind == kind;
    if (match) ++i;
    return match;
  };
  AZT_FUZZ_REQUIRE(next(CallKind::Stop) == command.stop);
  if (command.stop) AZT_FUZZ_REQUIRE(!calls[i - 1].axis);
  if (command.az_deg && command.el_deg) {
    AZT_FUZZ_REQUIRE(next(CallKind::GotoPosition));
    AZT_FUZZ_REQUIRE(calls[i - 1].az_deg == *command.az_deg);
    AZT_FUZZ_REQUIRE(calls[i - 1].el_deg == *command.el_deg);
  } else if (command.az_deg || command.el_deg) {
    AZT_FUZZ_REQUIRE(next(CallKind::GotoAxis));
    AZT_FUZZ_REQUIRE(calls[i - 1].axis == (command.az_deg ? proto::Axis::Az : proto::Axis::El));
    AZT_FUZZ_REQUIRE(calls[i - 1].az_deg == (command.az_deg ? *command.az_deg : *command.el_deg));
  }
  AZT_FUZZ_REQUIRE(next(CallKind::Park) == command.park);
  AZT_FUZZ_REQUIRE(next(CallKind::Position) == (command.query_az || command.query_el));
  AZT_FUZZ_REQUIRE(i == calls.size());
}

/// Case and surrounding white space do not change what a datagram means.
void check_parse_invariance(std::string_view datagram, const proto::TargetLimits& limits) {
  const auto parsed = proto::parse_pstrotator(datagram, limits);
  std::string upper(datagram);
  for (char& c : upper) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  const auto shouted = proto::parse_pstrotator(upper, limits);
  AZT_FUZZ_REQUIRE(shouted.ok() == parsed.ok());
  if (parsed) AZT_FUZZ_REQUIRE(*shouted == *parsed);
  if (datagram.size() + 4 <= proto::kPstMaxDatagramBytes) {
    const auto padded = proto::parse_pstrotator(" \t" + std::string(datagram) + "\r\n", limits);
    AZT_FUZZ_REQUIRE(padded.ok() == parsed.ok());
    if (parsed) AZT_FUZZ_REQUIRE(*padded == *parsed);
  }
}

void check_datagram(const fuzz::Setup& setup, std::string_view datagram) {
  const proto::TargetLimits limits = setup.limits();
  auto service = setup.make_service();
  const std::string reply =
      proto::handle_pstrotator_datagram(datagram, service, fuzz::kClient, limits);
  const std::span<const Call> calls(service.calls());
  AZT_FUZZ_REQUIRE(!calls.empty() && calls.front().kind == CallKind::Activity);
  const auto parsed = proto::parse_pstrotator(datagram, limits);
  if (!parsed) {
    AZT_FUZZ_REQUIRE(calls.size() == 1 && reply.empty());
  } else {
    check_requests(calls.subspan(1), *parsed);
    check_reply(reply, *parsed, service.report());
  }
  check_parse_invariance(datagram, limits);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::SessionInput in = fuzz::read_session_input(data, size);
  check_datagram(in.setup, in.payload);
  check_datagram(in.setup, in.payload.substr(0, in.split));
  check_datagram(in.setup, in.payload.substr(in.split));
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) { return azt::fuzz::replay_files("pstrotator_fuzz", argc, argv); }
#endif
