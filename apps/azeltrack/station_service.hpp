#pragma once
// The station as PC programs see it: RotatorService over the mode controller and the antenna.
// Who is in control: a program's target puts the station in EXT mode and names the client; a
// console STOP locks programs out until the console chooses again (ModeController).

#include <functional>
#include <string>

#include "antenna_backend.hpp"
#include "azt/control/modes.hpp"
#include "azt/proto/rotator_service.hpp"
#include "azt/proto/target_limits.hpp"

namespace azt::app {

class StationService final : public proto::RotatorService {
 public:
  using Clock = std::function<double()>;  ///< monotonic seconds
  using Log = std::function<void(const std::string&)>;

  StationService(control::ModeController& modes, AntennaBackend& antenna,
                 proto::TargetLimits limits, control::ElevationRange el_range, std::string info,
                 Clock now, Log log);

  [[nodiscard]] std::optional<proto::PositionReport> position() const override;
  proto::ServiceStatus goto_position(std::string_view client, double az_deg,
                                     double el_deg) override;
  proto::ServiceStatus goto_axis(std::string_view client, proto::Axis axis, double deg) override;
  proto::ServiceStatus move(std::string_view client, proto::AxisMotion motion) override;
  void stop(std::string_view client, std::optional<proto::Axis> axis) override;
  proto::ServiceStatus park(std::string_view client) override;
  void activity(std::string_view client) override;
  [[nodiscard]] std::string info() const override { return info_; }
  void refused(std::string_view client, std::string_view why) override {
    (void)refuse(client, proto::ServiceStatus::Invalid, std::string(why));
  }

 private:
  void announce(std::string_view client, const std::string& what);
  /// A latched fault refuses every motion request until an operator clears it; a client must not
  /// be told "RPRT 0" for a move that cannot happen.
  [[nodiscard]] bool faulted() const { return !antenna_.faults().empty(); }
  /// Logs a refusal the client was given (rate-limited by the daemon's log) and returns it.
  proto::ServiceStatus refuse(std::string_view client, proto::ServiceStatus status,
                              const std::string& why);

  control::ModeController& modes_;
  AntennaBackend& antenna_;
  proto::TargetLimits limits_;
  control::ElevationRange el_range_;
  std::string info_;
  Clock now_;
  Log log_;
  std::string last_announced_;
};

}  // namespace azt::app
