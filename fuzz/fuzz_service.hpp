#pragma once
// A recording RotatorService for the protocol fuzz targets. It answers with a fixed position and
// status picked from the input's control bytes, records every call (so two runs of the same bytes
// can be compared call for call) and checks, as each request arrives, what any session must
// guarantee the station: the right client name, finite targets inside the session's TargetLimits,
// continuous moves of −1/0/+1 per axis that move something, and no request at all once the
// session is finished.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/proto/rotator_service.hpp"
#include "azt/proto/sessions.hpp"
#include "azt/proto/target_limits.hpp"
#include "fuzz_support.hpp"

namespace azt::fuzz {

inline constexpr std::string_view kClient = "fuzz-client";

enum class CallKind { Position, Info, Activity, GotoPosition, GotoAxis, Move, Stop, Park };

/// One call made of the service. Fields a kind does not use stay at their defaults.
struct Call {
  CallKind kind = CallKind::Activity;
  std::optional<proto::Axis> axis;  ///< GotoAxis, Stop (nullopt: both axes)
  double az_deg = 0.0;              ///< GotoPosition, GotoAxis (the axis' angle)
  double el_deg = 0.0;              ///< GotoPosition
  int move_az = 0;
  int move_el = 0;
  bool operator==(const Call&) const = default;
};

inline Call call_of(CallKind kind) {
  Call call;
  call.kind = kind;
  return call;
}

inline std::size_t count_calls(const std::vector<Call>& calls, CallKind kind) {
  std::size_t n = 0;
  for (const Call& call : calls) n += call.kind == kind ? 1U : 0U;
  return n;
}

class FuzzRotatorService final : public proto::RotatorService {
 public:
  FuzzRotatorService(std::optional<proto::PositionReport> report, proto::ServiceStatus status,
                     std::string info, proto::TargetLimits limits)
      : report_(report), status_(status), info_(std::move(info)), limits_(limits) {}

  [[nodiscard]] std::optional<proto::PositionReport> position() const override {
    record(call_of(CallKind::Position));
    return report_;
  }
  proto::ServiceStatus goto_position(std::string_view client, double az_deg,
                                     double el_deg) override {
    check_request(client);
    AZT_FUZZ_REQUIRE(std::isfinite(az_deg) && limits_.accepts_az(az_deg));
    AZT_FUZZ_REQUIRE(std::isfinite(el_deg) && limits_.accepts_el(el_deg));
    Call call = call_of(CallKind::GotoPosition);
    call.az_deg = az_deg;
    call.el_deg = el_deg;
    record(call);
    return status_;
  }
  proto::ServiceStatus goto_axis(std::string_view client, proto::Axis axis, double deg) override {
    check_request(client);
    AZT_FUZZ_REQUIRE(std::isfinite(deg));
    AZT_FUZZ_REQUIRE(axis == proto::Axis::Az ? limits_.accepts_az(deg) : limits_.accepts_el(deg));
    Call call = call_of(CallKind::GotoAxis);
    call.axis = axis;
    call.az_deg = deg;
    record(call);
    return status_;
  }
  proto::ServiceStatus move(std::string_view client, proto::AxisMotion motion) override {
    check_request(client);
    AZT_FUZZ_REQUIRE(motion.az >= -1 && motion.az <= 1 && motion.el >= -1 && motion.el <= 1);
    AZT_FUZZ_REQUIRE(motion.az != 0 || motion.el != 0);
    Call call = call_of(CallKind::Move);
    call.move_az = motion.az;
    call.move_el = motion.el;
    record(call);
    return status_;
  }
  void stop(std::string_view client, std::optional<proto::Axis> axis) override {
    check_request(client);
    Call call = call_of(CallKind::Stop);
    call.axis = axis;
    record(call);
  }
  proto::ServiceStatus park(std::string_view client) override {
    check_request(client);
    record(call_of(CallKind::Park));
    return status_;
  }
  void activity(std::string_view client) override {
    check_request(client);
    record(call_of(CallKind::Activity));
  }
  [[nodiscard]] std::string info() const override {
    record(call_of(CallKind::Info));
    return info_;
  }

  [[nodiscard]] const std::vector<Call>& calls() const { return calls_; }
  [[nodiscard]] proto::ServiceStatus status() const { return status_; }
  [[nodiscard]] const std::optional<proto::PositionReport>& report() const { return report_; }
  void set_report(const std::optional<proto::PositionReport>& report) { report_ = report; }
  /// From now on any call is a failed invariant (the session said it is finished).
  void close() { closed_ = true; }

 private:
  void check_request(std::string_view client) const {
    AZT_FUZZ_REQUIRE(!closed_);
    AZT_FUZZ_REQUIRE(client == kClient);
  }
  void record(const Call& call) const {
    AZT_FUZZ_REQUIRE(!closed_);
    calls_.push_back(call);
  }

  std::optional<proto::PositionReport> report_;
  proto::ServiceStatus status_;
  std::string info_;
  proto::TargetLimits limits_;
  bool closed_ = false;
  mutable std::vector<Call> calls_;  ///< position() and info() are const but recorded too
};

/// Positions worth reporting (3 bits): unknown, ordinary, moving near the wrap, faulted, just
/// below zero (rounds to "-0.0"), at the overlap end, not finite, absurdly large.
inline std::optional<proto::PositionReport> pick_position(unsigned bits) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  switch (bits % 8) {
    case 0:
      return std::nullopt;
    case 1:
      return proto::PositionReport{123.4, 45.6, 123.4};
    case 2:
      return proto::PositionReport{359.96, 89.96, 719.96, true};
    case 3:
      return proto::PositionReport{0.0, 0.0, 0.0, false, true};
    case 4:
      return proto::PositionReport{-0.04, -5.0, -0.04};
    case 5:
      return proto::PositionReport{450.0, 180.0, 450.0, true};
    case 6:
      return proto::PositionReport{kNan, 10.0, kNan};
    default:
      return proto::PositionReport{1e300, -kInf, 1e300};
  }
}

/// Every ServiceStatus (2 bits).
inline proto::ServiceStatus pick_status(unsigned bits) {
  switch (bits % 4) {
    case 0:
      return proto::ServiceStatus::Ok;
    case 1:
      return proto::ServiceStatus::Invalid;
    case 2:
      return proto::ServiceStatus::Rejected;
    default:
      return proto::ServiceStatus::Unavailable;
  }
}

/// Session travel (2 bits): Hamlib's dummy default, a GS-232/EasyComm controller, a narrow
/// 0..360 / 10..80 mount, and an empty range (min > max) that must accept no target at all.
inline proto::TargetLimits pick_limits(unsigned bits) {
  switch (bits % 4) {
    case 0:
      return proto::TargetLimits{};
    case 1:
      return proto::TargetLimits{0.0, 450.0, 0.0, 180.0};
    case 2:
      return proto::TargetLimits{0.0, 360.0, 10.0, 80.0};
    default:
      return proto::TargetLimits{100.0, 50.0, 60.0, 30.0};
  }
}

/// The station's info line (1 bit): plain, or with line breaks a reply must not pass on.
inline std::string pick_info(unsigned bits) {
  return bits % 2 == 0 ? "azeltrack fuzz station" : "azeltrack\r\nfuzz station\n";
}

/// Control bytes 1 and 2 of an input, as every session target reads them:
///   flags[0..2] position, flags[3..4] status, flags[5..6] limits, flags[7] protocol variant,
///   flags[8] info text; bits 9..15 are free for a target's own choices.
struct Setup {
  unsigned flags = 0;
  [[nodiscard]] bool variant() const { return (flags >> 7U) % 2 == 1; }
  [[nodiscard]] unsigned extra() const { return flags >> 9U; }
  [[nodiscard]] proto::TargetLimits limits() const { return pick_limits(flags >> 5U); }
  [[nodiscard]] FuzzRotatorService make_service() const { return make_service(limits()); }
  [[nodiscard]] FuzzRotatorService make_service(proto::TargetLimits limits) const {
    return FuzzRotatorService(pick_position(flags), pick_status(flags >> 3U),
                              pick_info(flags >> 8U), limits);
  }
};

inline Setup read_setup(FuzzInput& input) {
  const unsigned low = input.take();
  const unsigned high = input.take();
  return Setup{low | high << 8U};
}

/// Feeds `bytes` to a session; once the session is finished the service is closed (any request
/// aborts) and the reply must be empty: after `finished()` nothing more is answered.
inline std::string feed_checked(proto::ProtocolSession& session, FuzzRotatorService& service,
                                std::string_view bytes) {
  const bool finished_before = session.finished();
  if (finished_before) service.close();
  std::string reply = session.feed(bytes);
  AZT_FUZZ_REQUIRE(!finished_before || (reply.empty() && session.finished()));
  return reply;
}

/// Cuts `bytes` after every byte for which `is_end` holds (the last piece may have no end byte).
template <typename IsEnd>
std::vector<std::string_view> split_after(std::string_view bytes, IsEnd is_end) {
  std::vector<std::string_view> pieces;
  std::size_t start = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (is_end(bytes[i])) {
      pieces.push_back(bytes.substr(start, i + 1 - start));
      start = i + 1;
    }
  }
  if (start < bytes.size()) pieces.push_back(bytes.substr(start));
  return pieces;
}

/// What one conversation produced.
struct Transcript {
  std::string replies;
  std::vector<Call> calls;
  bool finished = false;
  bool operator==(const Transcript&) const = default;
};

/// The input layout every protocol target shares: a byte choosing where to cut the payload in two,
/// two bytes of Setup, then the payload.
struct SessionInput {
  Setup setup;
  std::string_view payload;
  std::size_t split = 0;  ///< where to cut the payload in two
};

inline SessionInput read_session_input(const std::uint8_t* data, std::size_t size) {
  FuzzInput input(data, size);
  const std::uint8_t split_byte = input.take();
  SessionInput in;
  in.setup = read_setup(input);
  in.payload = input.rest();
  in.split = split_point(split_byte, in.payload.size());
  return in;
}

/// Feeds the payload to `run(setup, pieces, per_piece)` whole, cut in two, and cut after every
/// byte `is_end` accepts; the transcript must not depend on how the bytes arrived. Returns it.
template <typename Run, typename IsEnd>
Transcript same_however_fed(const Run& run, const SessionInput& in, IsEnd is_end) {
  const Transcript whole = run(in.setup, std::vector<std::string_view>{in.payload}, false);
  const Transcript halves = run(
      in.setup,
      std::vector<std::string_view>{in.payload.substr(0, in.split), in.payload.substr(in.split)},
      false);
  const Transcript pieces = run(in.setup, split_after(in.payload, is_end), true);
  AZT_FUZZ_REQUIRE(halves == whole);
  AZT_FUZZ_REQUIRE(pieces == whole);
  return whole;
}

/// Printable ASCII: what text protocols may send besides their line ends.
inline bool is_printable(char c) { return c >= ' ' && c <= '~'; }

}  // namespace azt::fuzz
