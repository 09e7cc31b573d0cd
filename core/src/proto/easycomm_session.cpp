// EasyComm I/II session: the CR/LF-framed assembler + parse_easycomm + the RotatorService (rules
// in sessions.hpp).
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "azt/proto/easycomm.hpp"
#include "azt/proto/sessions.hpp"

namespace azt::proto {
namespace {

/// EasyComm III status and error bits (reference §8.3: GS 1 idle, 2 moving, 8 error; GE 1 sensor).
constexpr int kStatusIdle = 1;
constexpr int kStatusMoving = 2;
constexpr int kStatusError = 8;
constexpr int kErrorSensor = 1;

/// What one line asks of the station, gathered so a line makes at most one request of each kind.
struct LineRequests {
  std::optional<double> az_deg;
  std::optional<double> el_deg;
  AxisMotion motion;
  bool stop_az = false;
  bool stop_el = false;
  bool park = false;
  bool needs_position = false;
  bool needs_info = false;
};

LineRequests gather(const EasyCommLine& line) {
  LineRequests requests;
  for (const EasyCommToken& token : line.tokens) {
    switch (token.op) {
      case EasyCommOp::SetAz:
        requests.az_deg = token.angle_deg;
        break;
      case EasyCommOp::SetEl:
        requests.el_deg = token.angle_deg;
        break;
      case EasyCommOp::MoveLeft:
      case EasyCommOp::MoveRight:
        requests.motion.az = token.op == EasyCommOp::MoveRight ? 1 : -1;
        break;
      case EasyCommOp::MoveUp:
      case EasyCommOp::MoveDown:
        requests.motion.el = token.op == EasyCommOp::MoveUp ? 1 : -1;
        break;
      case EasyCommOp::StopAz:
      case EasyCommOp::StopEl:
      case EasyCommOp::Reset:
        requests.stop_az = requests.stop_az || token.op != EasyCommOp::StopEl;
        requests.stop_el = requests.stop_el || token.op != EasyCommOp::StopAz;
        break;
      case EasyCommOp::Park:
        requests.park = true;
        break;
      case EasyCommOp::QueryAz:
      case EasyCommOp::QueryEl:
      case EasyCommOp::Status:
      case EasyCommOp::Errors:
        requests.needs_position = true;
        break;
      case EasyCommOp::Version:
        requests.needs_info = true;
        break;
      default:  // radio frequencies, modes and AOS/LOS ask nothing of the rotator
        break;
    }
  }
  return requests;
}

/// The queries to answer while the position is unknown: the first AZ/EL query becomes "GS GE",
/// later ones are dropped (one error status per line is enough).
EasyCommLine without_angles(const EasyCommLine& line) {
  EasyCommLine out;
  bool reported = false;
  for (const EasyCommToken& token : line.tokens) {
    const bool angle = token.op == EasyCommOp::QueryAz || token.op == EasyCommOp::QueryEl;
    if (!angle) {
      out.tokens.push_back(token);
    } else if (!reported) {
      out.tokens.push_back(EasyCommToken{EasyCommOp::Status});
      out.tokens.push_back(EasyCommToken{EasyCommOp::Errors});
      reported = true;
    }
  }
  return out;
}

/// `text` on one line: line breaks would end the reply early.
std::string single_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

class EasyCommSession final : public ProtocolSession {
 public:
  EasyCommSession(RotatorService& service, std::string client, EasyCommVersion version,
                  TargetLimits limits)
      : service_(service), client_(std::move(client)), version_(version), limits_(limits) {}

  std::string feed(std::string_view bytes) override {
    std::string out;
    for (const char byte : bytes) {
      const auto overlong_before = lines_.overlong_lines();
      const auto line = lines_.push(byte);
      dropping_ = dropping_ || lines_.overlong_lines() != overlong_before;
      if (line) {
        service_.activity(client_);
        out += answer(*line);
      } else if (dropping_ && (byte == '\r' || byte == '\n')) {
        // The end of an overlong line: traffic like any other line, but EasyComm has no error
        // reply for it.
        dropping_ = false;
        service_.activity(client_);
      }
    }
    return out;
  }

 private:
  std::string answer(std::string_view text) {
    const auto line = parse_easycomm(text, version_, limits_);
    if (!line) {
      service_.refused(client_, line.error().message);
      return {};  // EasyComm has no error reply
    }
    const LineRequests requests = gather(*line);
    perform(requests);
    const std::string info = requests.needs_info ? single_line(service_.info()) : std::string();
    EasyCommState state;
    state.version = info;
    if (!requests.needs_position) return format_easycomm_reply(*line, state);
    const auto position = service_.position();
    if (!position) {
      state.status_bits = kStatusError;
      state.error_bits = kErrorSensor;
      return format_easycomm_reply(without_angles(*line), state);
    }
    state.az_deg = position->az_deg;
    state.el_deg = position->el_deg;
    state.status_bits = position->fault    ? kStatusError
                        : position->moving ? kStatusMoving
                                           : kStatusIdle;
    state.error_bits = position->fault ? kErrorSensor : 0;
    return format_easycomm_reply(*line, state);
  }

  /// Requests in a fixed order: stop, then targets, then moves, then park.
  void perform(const LineRequests& requests) {
    if (requests.stop_az && requests.stop_el) {
      service_.stop(client_, std::nullopt);
    } else if (requests.stop_az || requests.stop_el) {
      service_.stop(client_, requests.stop_az ? Axis::Az : Axis::El);
    }
    if (requests.az_deg && requests.el_deg) {
      service_.goto_position(client_, *requests.az_deg, *requests.el_deg);
    } else if (requests.az_deg) {
      service_.goto_axis(client_, Axis::Az, *requests.az_deg);
    } else if (requests.el_deg) {
      service_.goto_axis(client_, Axis::El, *requests.el_deg);
    }
    if (requests.motion.az != 0 || requests.motion.el != 0) service_.move(client_, requests.motion);
    if (requests.park) service_.park(client_);
  }

  RotatorService& service_;
  std::string client_;
  EasyCommVersion version_;
  TargetLimits limits_;
  BoundedLineAssembler lines_ = make_easycomm_assembler();
  bool dropping_ = false;  ///< inside an overlong line, waiting for its CR or LF
};

}  // namespace

std::unique_ptr<ProtocolSession> make_easycomm_session(RotatorService& service, std::string client,
                                                       EasyCommVersion version,
                                                       TargetLimits limits) {
  return std::make_unique<EasyCommSession>(service, std::move(client), version, limits);
}

}  // namespace azt::proto
