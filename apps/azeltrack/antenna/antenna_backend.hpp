#pragma once

// The antenna behind the daemon: the simulated one (plants, hub link and the station's own
// controller), or an existing rotator controller driven through Hamlib.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/control/corrections.hpp"
#include "azt/control/modes.hpp"
#include "azt/control/pol_axis.hpp"
#include "azt/control/station_controller.hpp"
#include "azt/proto/rotator_service.hpp"
#include "azt/sim/plant_rig.hpp"
#include "config/daemon_config.hpp"

namespace boost::asio {
class io_context;
}  // namespace boost::asio

namespace azt::app {

/// The polarisation axis as the station knows it (docs/eme.md, "Polarisation axis").
struct PolStatus {
  double mount_deg = 0.0;                  ///< the last accepted reading, feed degrees
  std::optional<double> target_mount_deg;  ///< where it was last sent; nullopt while it holds
  bool moving = false;
  std::string fault;     ///< the supervisor's words when faulted, else empty
  double min_deg = 0.0;  ///< the travel ([mount.pol])
  double max_deg = 0.0;
};

/// One motor axis as the station's own controller knows it: its brake, its motor's readings and a
/// pulse-counted axis's homing (docs/hardware.md). `axis` is "az", "el" or "pol".
struct NamedAxisStatus {
  std::string axis;
  control::AxisStatus status;
};

class AntennaBackend {
 public:
  AntennaBackend() = default;
  AntennaBackend(const AntennaBackend&) = delete;
  AntennaBackend& operator=(const AntennaBackend&) = delete;
  virtual ~AntennaBackend() = default;

  /// One control tick at `now_s` (monotonic seconds): move towards `demand`. `rate` is the
  /// target's sky rate (deg/s) for feed-forward.
  virtual void tick(double now_s, const control::Demand& demand, const control::AzEl& rate) = 0;
  /// nullopt while the position is unknown (stale sensors, lost link).
  [[nodiscard]] virtual std::optional<proto::PositionReport> position(double now_s) const = 0;
  /// Motors off now (shutdown, fatal paths).
  virtual void stop_now(double now_s) = 0;
  /// Latched faults in words (empty when healthy).
  [[nodiscard]] virtual std::vector<std::string> faults() const = 0;
  virtual void clear_faults() = 0;
  /// The Offset / ± / UP / DWN / tilt settings, applied to every reading from now on (a Hamlib
  /// box's reports too: the station's controller reads them as any sensor).
  virtual void set_corrections(const control::PositionCorrections& corrections) = 0;
  /// The encoder angles as read, before corrections; nullopt when there are no encoders of ours.
  [[nodiscard]] virtual std::optional<control::AzEl> encoder_reading() const = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
  /// The polarisation axis's wish for the next ticks (pol_axis.hpp; nullopt feed: it holds). A
  /// backend without a pol axis ignores it.
  virtual void set_pol_demand(const control::PolDemand& demand) { (void)demand; }
  /// The polarisation axis; nullopt when the station has none (a Hamlib box never has one).
  [[nodiscard]] virtual std::optional<PolStatus> pol_status() const { return std::nullopt; }
  /// The travel-end switches changed (an input edge, between ticks): a drive towards a tripped
  /// switch goes off now. A Hamlib rotator has its own limit switches, so the default ignores
  /// them.
  virtual void set_limits(double now_s, const control::LimitSwitches& limits) {
    (void)now_s;
    (void)limits;
  }
  /// The axes this station drives itself (the fixed elevation is none); empty for a Hamlib box,
  /// which keeps its brakes and motors to itself.
  [[nodiscard]] virtual std::vector<NamedAxisStatus> axes() const { return {}; }
  /// The operator's command to home the pulse-counted axis `axis` ("az", "el" or "pol"): nullopt
  /// when homing began, else why not.
  virtual std::optional<std::string> home(double now_s, const std::string& axis) {
    (void)now_s;
    (void)axis;
    return std::string{"this antenna has no pulse-counted axis to home"};
  }
  /// A STOP from any source: every homing in progress ends, the axes unreferenced.
  virtual void stop_homing(double now_s, std::string_view reason) {
    (void)now_s;
    (void)reason;
  }
  /// The polarisation axis's switches changed; a backend without a pol axis ignores them.
  virtual void set_pol_limits(double now_s, const control::LimitPair& limits) {
    (void)now_s;
    (void)limits;
  }
};

/// The EncoderHub on a serial device and two IBT-2 bridges on sysfs PWM ([hub], [pwm]); throws
/// UsageError naming the device or channel that cannot be opened (nothing is driven then).
std::unique_ptr<AntennaBackend> make_pwm_backend(boost::asio::io_context& io,
                                                 const DaemonConfig& config);
struct HardwarePorts;
/// Per-axis drives and sensors ([hardware.az] / [hardware.el]) on the devices `ports` opens;
/// throws UsageError naming the key of a device that cannot be had (nothing is driven then).
std::unique_ptr<AntennaBackend> make_hardware_backend(boost::asio::io_context& io,
                                                      const DaemonConfig& config,
                                                      HardwarePorts ports);
/// The simulated antenna of the [sim] tables, in real time; `truth`, when given, receives the
/// rig behind it (the plants' true shaft angles, for the simulated receiver).
std::unique_ptr<AntennaBackend> make_sim_backend(
    const DaemonConfig& config, std::shared_ptr<const sim::PlantRig>* truth = nullptr);
/// A Hamlib rotator ([hamlib]); throws UsageError naming the model/device when it cannot open.
std::unique_ptr<AntennaBackend> make_hamlib_backend(const DaemonConfig& config);

}  // namespace azt::app
