// libFuzzer target for the SPID Rot2Prog/Rot1Prog session (make_spid_session: SpidFrameAssembler
// + parse_spid + a RotatorService) and the set-frame codec, reliability notes R24.
//
// Input: byte 0 is where to cut the payload for the split feed, bytes 1-2 pick the station
// (fuzz_service.hpp Setup) and the emulated controller: the variant bit chooses Rot1Prog, the
// extra bits the pulses per degree (1, 2, 4, or an invalid 3) and the set range. The rest is what
// the client sends. The payload is fed at once, in two pieces cut at byte 0, and byte by byte.
// Invariants:
// - all three give the same replies and the same calls of the service;
// - every target is finite and inside the SpidConfig range (checked by the fake service);
//   Rot2Prog sets both axes, Rot1Prog azimuth only;
// - byte by byte: activity() only when the last 13 bytes are a frame ('W' .. K 0x20, K known);
//   a set frame gets no reply, and the target it makes encodes (encode_spid_set) back to the
//   frame's digits; a stop frame stops both axes; stop and status get one reply frame of the
//   dialect ('W', digits 0..9, the configured PH/PV, 0x20) that decodes to the position within
//   half a step, and always get one while the position is known and well inside the window;
//   nothing is answered with an invalid pulses-per-degree setting;
// - encode_spid_set → parse_spid round-trips angles read from the payload (truncated by at
//   most one pulse), and a fresh session turns the encoded frame into that very target.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "azt/proto/sessions.hpp"
#include "azt/proto/spid.hpp"
#include "fuzz_service.hpp"
#include "fuzz_support.hpp"

namespace {

namespace proto = azt::proto;
namespace fuzz = azt::fuzz;
using fuzz::Call;
using fuzz::CallKind;

/// Pulses per degree from two bits: the three a controller has, and one it cannot have.
int pick_pulses(unsigned bits) {
  constexpr int kPulses[] = {1, 2, 4, 3};
  return kPulses[bits % 4];
}

proto::SpidConfig pick_config(const fuzz::Setup& setup) {
  proto::SpidConfig config;
  config.dialect = setup.variant() ? proto::SpidDialect::Rot1Prog : proto::SpidDialect::Rot2Prog;
  config.pulses_per_deg_az = pick_pulses(setup.extra());
  config.pulses_per_deg_el = pick_pulses(setup.extra() >> 2U);
  if ((setup.extra() >> 4U) % 2 == 1) {  // a plain 0..360 / 0..90 rotator
    config.az_min_deg = 0.0;
    config.az_max_deg = 360.0;
    config.el_min_deg = 0.0;
    config.el_max_deg = 90.0;
  }
  return config;
}

proto::TargetLimits limits_of(const proto::SpidConfig& config) {
  return {config.az_min_deg, config.az_max_deg, config.el_min_deg, config.el_max_deg};
}

bool valid_pulses(const proto::SpidConfig& config) {
  return config.pulses_per_deg_az != 3 && config.pulses_per_deg_el != 3;
}

bool is_rot1(const proto::SpidConfig& config) {
  return config.dialect == proto::SpidDialect::Rot1Prog;
}

std::size_t reply_bytes(const proto::SpidConfig& config) {
  return is_rot1(config) ? proto::kSpidRot1ReplyBytes : proto::kSpidRot2ReplyBytes;
}

bool is_digit_value(std::uint8_t byte) { return byte <= 9; }

/// Binary digits to a number: "az = H1*100 + H2*10 + H3 + H4/10 - 360" (spid.hpp).
double decode_digits(std::string_view digits) {
  double value = 0.0;
  for (const char c : digits) value = value * 10.0 + static_cast<std::uint8_t>(c);
  return value;
}

void check_reply_frame(std::string_view reply, const proto::SpidConfig& config,
                       const proto::PositionReport& position) {
  AZT_FUZZ_REQUIRE(reply.size() == reply_bytes(config));
  AZT_FUZZ_REQUIRE(static_cast<std::uint8_t>(reply.front()) == proto::kSpidStart);
  AZT_FUZZ_REQUIRE(static_cast<std::uint8_t>(reply.back()) == proto::kSpidEnd);
  if (is_rot1(config)) {
    for (const char c : reply.substr(1, 3)) {
      AZT_FUZZ_REQUIRE(is_digit_value(static_cast<std::uint8_t>(c)));
    }
    AZT_FUZZ_REQUIRE(std::fabs(decode_digits(reply.substr(1, 3)) - 360.0 - position.az_deg) <=
                     0.5 + 1e-9);
    return;
  }
  for (const std::size_t i : {1U, 2U, 3U, 4U, 6U, 7U, 8U, 9U}) {
    AZT_FUZZ_REQUIRE(is_digit_value(static_cast<std::uint8_t>(reply[i])));
  }
  AZT_FUZZ_REQUIRE(reply[5] == static_cast<char>(config.pulses_per_deg_az));
  AZT_FUZZ_REQUIRE(reply[10] == static_cast<char>(config.pulses_per_deg_el));
  AZT_FUZZ_REQUIRE(std::fabs(decode_digits(reply.substr(1, 4)) / 10.0 - 360.0 - position.az_deg) <=
                   0.05 + 1e-9);
  AZT_FUZZ_REQUIRE(std::fabs(decode_digits(reply.substr(6, 4)) / 10.0 - 360.0 - position.el_deg) <=
                   0.05 + 1e-9);
}

/// The set a session made re-encodes to the digits of the frame it came from.
void check_set(std::string_view frame, const Call& call, const proto::SpidConfig& config) {
  const double el_deg = is_rot1(config) ? 0.0 : call.el_deg;
  AZT_FUZZ_REQUIRE(is_rot1(config)
                       ? (call.kind == CallKind::GotoAxis && call.axis == proto::Axis::Az)
                       : call.kind == CallKind::GotoPosition);
  const auto encoded = proto::encode_spid_set(call.az_deg, el_deg, config);
  AZT_FUZZ_REQUIRE(encoded.ok());
  const std::vector<std::size_t> compared =
      is_rot1(config) ? std::vector<std::size_t>{0, 1, 2, 3, 4, 11, 12}
                      : std::vector<std::size_t>{0, 1, 2, 3, 4, 6, 7, 8, 9, 11, 12};
  for (const std::size_t i : compared) {
    AZT_FUZZ_REQUIRE((*encoded)[i] == static_cast<std::uint8_t>(frame[i]));
  }
}

/// After byte `end` (exclusive) of `payload` was fed alone.
void check_byte(std::string_view payload, std::size_t end, std::string_view reply,
                std::span<const Call> calls, const fuzz::FuzzRotatorService& service,
                const proto::SpidConfig& config) {
  if (calls.empty()) {
    AZT_FUZZ_REQUIRE(reply.empty());
    return;
  }
  AZT_FUZZ_REQUIRE(calls.front().kind == CallKind::Activity && end >= proto::kSpidCommandBytes);
  const std::string_view frame =
      payload.substr(end - proto::kSpidCommandBytes, proto::kSpidCommandBytes);
  const auto k = static_cast<std::uint8_t>(frame[11]);
  AZT_FUZZ_REQUIRE(static_cast<std::uint8_t>(frame[0]) == proto::kSpidStart);
  AZT_FUZZ_REQUIRE(static_cast<std::uint8_t>(frame[12]) == proto::kSpidEnd);
  AZT_FUZZ_REQUIRE(k == proto::kSpidKStop || k == proto::kSpidKStatus || k == proto::kSpidKSet);
  const std::span<const Call> rest = calls.subspan(1);
  if (!valid_pulses(config)) {
    AZT_FUZZ_REQUIRE(rest.empty() && reply.empty());
    return;
  }
  if (k == proto::kSpidKSet) {
    AZT_FUZZ_REQUIRE(reply.empty() && rest.size() <= 1);
    if (!rest.empty()) check_set(frame, rest.front(), config);
    return;
  }
  std::size_t i = 0;
  if (k == proto::kSpidKStop) {
    AZT_FUZZ_REQUIRE(!rest.empty() && rest[0].kind == CallKind::Stop && !rest[0].axis);
    i = 1;
  }
  AZT_FUZZ_REQUIRE(rest.size() == i + 1 && rest[i].kind == CallKind::Position);
  const auto& position = service.report();
  if (!reply.empty()) {
    AZT_FUZZ_REQUIRE(position.has_value());
    check_reply_frame(reply, config, *position);
  } else if (position) {
    const bool inside =
        std::fabs(position->az_deg) <= 270.0 && std::fabs(position->el_deg) <= 270.0;
    AZT_FUZZ_REQUIRE(!inside);  // only an unreportable position goes unanswered
  }
}

fuzz::Transcript run(const fuzz::Setup& setup, const std::vector<std::string_view>& pieces,
                     std::string_view payload, bool byte_checks) {
  const proto::SpidConfig config = pick_config(setup);
  auto service = setup.make_service(limits_of(config));
  const auto session = proto::make_spid_session(service, std::string(fuzz::kClient), config);
  fuzz::Transcript out;
  std::size_t fed = 0;
  for (const std::string_view piece : pieces) {
    const std::size_t calls_before = service.calls().size();
    const std::string reply = fuzz::feed_checked(*session, service, piece);
    fed += piece.size();
    if (byte_checks) {
      check_byte(payload, fed, reply, std::span<const Call>(service.calls()).subspan(calls_before),
                 service, config);
    }
    out.replies += reply;
  }
  AZT_FUZZ_REQUIRE(!session->finished());
  out.calls = service.calls();
  return out;
}

/// A signed 16-bit number from two payload bytes, as degrees in steps of 1/50 (about ±655°).
double angle_from(std::string_view bytes) {
  const auto raw = static_cast<std::int16_t>(static_cast<std::uint8_t>(bytes[0]) << 8U |
                                             static_cast<std::uint8_t>(bytes[1]));
  return raw / 50.0;
}

/// encode_spid_set then parse_spid: the target comes back truncated to the pulse below it.
void check_round_trips(const fuzz::Setup& setup, std::string_view payload) {
  const proto::SpidConfig config = pick_config(setup);
  if (!valid_pulses(config)) return;
  const proto::TargetLimits limits = limits_of(config);
  for (std::size_t i = 0; i + 4 <= payload.size() && i < 64; i += 4) {
    const double az_deg = angle_from(payload.substr(i, 2));
    const double el_deg = is_rot1(config) ? 0.0 : angle_from(payload.substr(i + 2, 2));
    const auto frame = proto::encode_spid_set(az_deg, el_deg, config);
    if (!frame) continue;
    const auto command = proto::parse_spid(std::span<const std::uint8_t>(*frame), config);
    if (!limits.accepts_az(az_deg) || !limits.accepts_el(el_deg)) continue;
    AZT_FUZZ_REQUIRE(command.ok() && command->op == proto::SpidOp::Set);
    const double az_step = is_rot1(config) ? 1.0 : 1.0 / config.pulses_per_deg_az;
    AZT_FUZZ_REQUIRE(command->az_deg <= az_deg && command->az_deg > az_deg - az_step - 1e-9);
    if (!is_rot1(config)) {
      const double el_step = 1.0 / config.pulses_per_deg_el;
      AZT_FUZZ_REQUIRE(command->el_deg <= el_deg && command->el_deg > el_deg - el_step - 1e-9);
    }
    auto service = setup.make_service(limits);
    const auto session = proto::make_spid_session(service, std::string(fuzz::kClient), config);
    std::string bytes;
    for (const std::uint8_t byte : *frame) bytes.push_back(static_cast<char>(byte));
    AZT_FUZZ_REQUIRE(session->feed(bytes).empty());
    AZT_FUZZ_REQUIRE(service.calls().size() == 2);
    const Call& call = service.calls()[1];
    AZT_FUZZ_REQUIRE(call.az_deg == command->az_deg);
    AZT_FUZZ_REQUIRE(is_rot1(config) || call.el_deg == command->el_deg);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::SessionInput in = fuzz::read_session_input(data, size);
  const fuzz::Setup& setup = in.setup;
  const std::string_view payload = in.payload;
  // Whole, in two, and one byte at a time.
  const fuzz::Transcript whole = fuzz::same_however_fed(
      [payload](const fuzz::Setup& s, const std::vector<std::string_view>& pieces, bool each) {
        return run(s, pieces, payload, each);
      },
      in, [](char) { return true; });

  const proto::SpidConfig config = pick_config(setup);
  const std::size_t activities = fuzz::count_calls(whole.calls, CallKind::Activity);
  AZT_FUZZ_REQUIRE(activities <= payload.size() / proto::kSpidCommandBytes);
  AZT_FUZZ_REQUIRE(whole.replies.size() % reply_bytes(config) == 0);
  AZT_FUZZ_REQUIRE(whole.replies.size() <= reply_bytes(config) * activities);
  check_round_trips(setup, payload);
  return 0;
}

#ifdef AZT_FUZZ_STANDALONE
int main(int argc, char** argv) { return azt::fuzz::replay_files("spid_session_fuzz", argc, argv); }
#endif
