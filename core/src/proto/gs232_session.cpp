// GS-232A/B session: the CR-framed assembler + parse_gs232 + the RotatorService (rules in
// sessions.hpp).
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "azt/proto/gs232.hpp"
#include "azt/proto/sessions.hpp"

namespace azt::proto {
namespace {

constexpr char kGs232Terminator = '\r';

class Gs232Session final : public ProtocolSession {
 public:
  Gs232Session(RotatorService& service, std::string client, Gs232Variant variant,
               TargetLimits limits)
      : service_(service), client_(std::move(client)), limits_(limits) {
    options_.variant = variant;
  }

  std::string feed(std::string_view bytes) override {
    std::string out;
    for (const char byte : bytes) {
      const auto overlong_before = lines_.overlong_lines();
      const auto line = lines_.push(byte);
      dropping_ = dropping_ || lines_.overlong_lines() != overlong_before;
      if (line) {
        service_.activity(client_);
        out += answer(*line);
      } else if (dropping_ && byte == kGs232Terminator) {
        // The end of an overlong line: the controller answers garbage with "?>".
        dropping_ = false;
        service_.activity(client_);
        out += format_gs232_error();
      }
    }
    return out;
  }

 private:
  std::string answer(std::string_view line) {
    const auto command = parse_gs232(line, limits_);
    if (!command) {
      service_.refused(client_, command.error().message);
      return format_gs232_error();
    }
    const auto status = execute(*command);
    if (status != ServiceStatus::Ok) return format_gs232_error();
    double az_deg = std::nan("");
    double el_deg = std::nan("");
    if (is_query(command->op)) {
      // An unknown position stays NaN, which the formatter answers with "?>".
      if (const auto position = service_.position()) {
        az_deg = position->az_deg;
        el_deg = position->el_deg;
      }
    }
    return format_gs232_reply(*command, az_deg, el_deg, options_);
  }

  static bool is_query(Gs232Op op) {
    return op == Gs232Op::QueryAz || op == Gs232Op::QueryAzEl || op == Gs232Op::QueryEl;
  }

  /// Performs the command's request, if it makes one.
  ServiceStatus execute(const Gs232Command& command) {
    switch (command.op) {
      case Gs232Op::GotoAzEl:
        return service_.goto_position(client_, command.az_deg, command.el_deg);
      case Gs232Op::GotoAz:
        return service_.goto_axis(client_, Axis::Az, command.az_deg);
      case Gs232Op::StopAll:
        service_.stop(client_, std::nullopt);
        return ServiceStatus::Ok;
      case Gs232Op::StopAz:
        service_.stop(client_, Axis::Az);
        return ServiceStatus::Ok;
      case Gs232Op::StopEl:
        service_.stop(client_, Axis::El);
        return ServiceStatus::Ok;
      case Gs232Op::RotateCcw:
        return service_.move(client_, AxisMotion{-1, 0});
      case Gs232Op::RotateCw:
        return service_.move(client_, AxisMotion{1, 0});
      case Gs232Op::ElevateUp:
        return service_.move(client_, AxisMotion{0, 1});
      case Gs232Op::ElevateDown:
        return service_.move(client_, AxisMotion{0, -1});
      default:
        return ServiceStatus::Ok;
    }
  }

  RotatorService& service_;
  std::string client_;
  TargetLimits limits_;
  Gs232ReplyOptions options_;
  BoundedLineAssembler lines_ = make_gs232_assembler();
  bool dropping_ = false;  ///< inside an overlong line, waiting for its CR
};

}  // namespace

std::unique_ptr<ProtocolSession> make_gs232_session(RotatorService& service, std::string client,
                                                    Gs232Variant variant, TargetLimits limits) {
  return std::make_unique<Gs232Session>(service, std::move(client), variant, limits);
}

}  // namespace azt::proto
