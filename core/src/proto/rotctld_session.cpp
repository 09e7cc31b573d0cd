// rotctld session: LineAssembler + parse_rotctld_line + the RotatorService (rules in sessions.hpp).
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "azt/proto/rotctld.hpp"
#include "azt/proto/sessions.hpp"

namespace azt::proto {
namespace {

/// Hamlib's move directions as per-axis steps (rotator.h: LEFT is CCW, i.e. azimuth −1).
AxisMotion motion_of(MoveDirection direction) {
  switch (direction) {
    case MoveDirection::Up:
      return {0, 1};
    case MoveDirection::Down:
      return {0, -1};
    case MoveDirection::Left:
      return {-1, 0};
    case MoveDirection::Right:
      return {1, 0};
    case MoveDirection::UpLeft:
      return {-1, 1};
    case MoveDirection::UpRight:
      return {1, 1};
    case MoveDirection::DownLeft:
      return {-1, -1};
    case MoveDirection::DownRight:
      return {1, -1};
  }
  return {};
}

class RotctldSession final : public ProtocolSession {
 public:
  RotctldSession(RotatorService& service, std::string client, TargetLimits limits)
      : service_(service), client_(std::move(client)), limits_(limits) {}

  std::string feed(std::string_view bytes) override {
    std::string out;
    lines_.feed(bytes, [this, &out](std::string_view line, LineStatus status) {
      if (finished_) return;  // the client said goodbye; the transport closes after this write
      service_.activity(client_);
      out += status == LineStatus::Overlong ? format_rprt(kRprtInvalid, {}, {}) : answer(line);
    });
    return out;
  }

  [[nodiscard]] bool finished() const override { return finished_; }

 private:
  std::string answer(std::string_view line) {
    auto parsed = parse_rotctld_line(line, limits_);
    if (const auto* error = std::get_if<RotctldError>(&parsed)) {
      service_.refused(client_, error->message);
      return format_error(*error);
    }
    return execute(std::get<RotctldCommand>(parsed));
  }

  std::string execute(const RotctldCommand& command) {
    switch (command.kind) {
      case RotctldCommandKind::SetPos:
        return format_status(
            command, rprt_code(service_.goto_position(client_, command.az_deg, command.el_deg)));
      case RotctldCommandKind::GetPos:
        return get_pos(command);
      case RotctldCommandKind::Stop:
      case RotctldCommandKind::Reset:  // a reset must at least leave the rotator standing still
        service_.stop(client_, std::nullopt);
        return format_status(command, kRprtOk);
      case RotctldCommandKind::Park:
        return format_status(command, rprt_code(service_.park(client_)));
      case RotctldCommandKind::Move:
        return format_status(command,
                             rprt_code(service_.move(client_, motion_of(command.direction))));
      case RotctldCommandKind::GetInfo:
        return format_get_info(command, service_.info());
      case RotctldCommandKind::DumpState:
        return format_dump_state(command, limits_);
      case RotctldCommandKind::Quit:
        finished_ = true;
        return {};
      case RotctldCommandKind::Ignore:
        return {};
    }
    return {};
  }

  std::string get_pos(const RotctldCommand& command) const {
    const auto position = service_.position();
    if (!position) return format_status(command, kRprtIo);
    return format_get_pos(command, position->az_deg, position->el_deg);
  }

  RotatorService& service_;
  std::string client_;
  TargetLimits limits_;
  LineAssembler lines_;
  bool finished_ = false;
};

}  // namespace

int rprt_code(ServiceStatus status) {
  switch (status) {
    case ServiceStatus::Ok:
      return kRprtOk;
    case ServiceStatus::Invalid:
      return kRprtInvalid;
    case ServiceStatus::Rejected:
      return kRprtRejected;
    case ServiceStatus::Unavailable:
      return kRprtIo;
  }
  return kRprtIo;
}

std::unique_ptr<ProtocolSession> make_rotctld_session(RotatorService& service, std::string client,
                                                      TargetLimits limits) {
  return std::make_unique<RotctldSession>(service, std::move(client), limits);
}

}  // namespace azt::proto
