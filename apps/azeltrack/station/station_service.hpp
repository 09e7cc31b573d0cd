#pragma once
// The station as PC programs see it: RotatorService over the station's front door
// (station_commands.hpp), which applies the same rules to every source. Who is in control: a
// program's target puts the station in EXT mode and names the client; a console STOP locks
// programs out until the console chooses again (ModeController).

#include <functional>
#include <string>

#include "azt/proto/rotator_service.hpp"
#include "station/station_commands.hpp"

namespace azt::app {

class StationService final : public proto::RotatorService {
 public:
  using Log = std::function<void(const std::string&)>;

  StationService(StationCommands& commands, const control::ModeController& modes,
                 AntennaBackend& antenna, std::function<double()> now, std::string info, Log log);

  [[nodiscard]] std::optional<proto::PositionReport> position() const override;
  proto::ServiceStatus goto_position(std::string_view client, double az_deg,
                                     double el_deg) override;
  proto::ServiceStatus goto_axis(std::string_view client, proto::Axis axis, double deg) override;
  proto::ServiceStatus move(std::string_view client, proto::AxisMotion motion) override;
  void stop(std::string_view client, std::optional<proto::Axis> axis) override;
  proto::ServiceStatus park(std::string_view client) override;
  void activity(std::string_view client) override;
  [[nodiscard]] std::string info() const override { return info_; }
  void refused(std::string_view client, std::string_view why) override;

 private:
  static CommandSource program(std::string_view client) {
    return CommandSource{CommandSource::Kind::Program, std::string(client)};
  }
  static proto::ServiceStatus status_of(const CommandOutcome& outcome) {
    return outcome.accepted() ? proto::ServiceStatus::Ok : outcome.refusal->status;
  }

  StationCommands& commands_;
  const control::ModeController& modes_;
  AntennaBackend& antenna_;
  std::function<double()> now_;
  std::string info_;
  Log log_;
};

}  // namespace azt::app
