#pragma once
// The antenna as the daemon drives it: a backend behind the station's hard inputs
// (docs/hardware.md): the E-stop, the travel-end switches, and the T/R sequencer's motion hold.
//
// E-stop: the input going active stops the drives, puts the mode to STOP, releases the PTT chain
// and latches. The latch is written to a file, so a restart (or a crash) with the button released
// still starts stopped; only the operator's "clear faults" lifts it, and only once the input is
// released. Limit switches act on their edge, between control ticks.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antenna/antenna_backend.hpp"
#include "azt/linux/gpio.hpp"
#include "common/off_loop.hpp"
#include "config/daemon_config.hpp"
#include "station/sequencer_runner.hpp"

namespace azt::app {

struct GuardParts {
  linux_os::GpioProvider* gpio = nullptr;  ///< null when no [gpio] line is configured
  SequencerRunner* sequencer = nullptr;    ///< null: no sequencer hold or release
  std::string latch_path;                  ///< the E-stop latch file
  std::function<double()> now_s;           ///< the control loop's clock
  std::function<void()> on_estop;          ///< the daemon's reaction (mode to STOP)
  std::function<void(const std::string&)> log;
  /// Where the latch file is written (an fsync): the daemon's worker, never the loop. Writes and
  /// removals run in the order asked, so a clear after a latch leaves no file.
  Offload offload = run_inline;
};

class GuardedAntenna final : public AntennaBackend {
 public:
  /// Requests the input lines of `gpio`; throws UsageError naming the key of a line that cannot
  /// be had. Reads the latch file: a latch left by an earlier run stops the antenna at once.
  GuardedAntenna(std::unique_ptr<AntennaBackend> inner, const GpioConfig& gpio, GuardParts parts);

  void tick(double now_s, const control::Demand& demand, const control::AzEl& rate) override;
  [[nodiscard]] std::optional<proto::PositionReport> position(double now_s) const override;
  void stop_now(double now_s) override;
  [[nodiscard]] std::vector<std::string> faults() const override;
  /// Clears the backend's faults and the sequencer's; the E-stop latch only when its input is
  /// released.
  void clear_faults() override;
  void set_corrections(const control::PositionCorrections& corrections) override;
  [[nodiscard]] std::optional<control::AzEl> encoder_reading() const override;
  [[nodiscard]] std::string describe() const override;
  void set_limits(double now_s, const control::LimitSwitches& limits) override;
  /// The pol axis holds while the E-stop is latched. The sequencer's and WSJT-X's motion hold
  /// are for azimuth and elevation: the pol axis follows its own rule while keyed ([pol]
  /// hold_while_keyed; a split turns it on the PTT by design).
  void set_pol_demand(const control::PolDemand& demand) override;
  [[nodiscard]] std::optional<PolStatus> pol_status() const override {
    return inner_->pol_status();
  }
  [[nodiscard]] std::vector<NamedAxisStatus> axes() const override { return inner_->axes(); }
  /// Homing moves the axis: refused while the E-stop is latched or the transmitter holds motion.
  std::optional<std::string> home(double now_s, const std::string& axis) override;
  void stop_homing(double now_s, std::string_view reason) override {
    inner_->stop_homing(now_s, reason);
  }

  /// Another program's transmit hold (WSJT-X transmitting, docs/radio.md): held as the
  /// sequencer's motion hold is.
  void set_other_hold(std::function<bool()> hold) { other_hold_ = std::move(hold); }
  [[nodiscard]] bool estop_latched() const { return latched_; }
  /// The instant (the tick's clock) of the first tick that held the antenna, for any cause, in
  /// the hold that goes on now; none while not held. What /api/state shows as the hold's start.
  [[nodiscard]] std::optional<double> held_since_s() const { return held_since_s_; }
  [[nodiscard]] const control::LimitSwitches& limits() const { return limits_; }
  /// {"estop": {"wired","input","latched"}, "limits": {...} | null}; the limits hold pol_ccw and
  /// pol_cw when those switches are wired.
  [[nodiscard]] nlohmann::json state() const;

 private:
  /// Why the antenna is held now (the E-stop latched, the transmitter keyed); nullopt: free.
  [[nodiscard]] std::optional<std::string> hold_reason() const;
  void on_limit_edge();
  void on_estop_input(bool active);
  void latch(const std::string& why);
  std::unique_ptr<linux_os::GpioInput> request(const linux_os::GpioLineSpec& spec,
                                               linux_os::GpioEdgeHandler on_edge);

  std::unique_ptr<AntennaBackend> inner_;
  GuardParts parts_;
  std::unique_ptr<linux_os::GpioInput> estop_;
  std::unique_ptr<linux_os::GpioInput> az_ccw_;
  std::unique_ptr<linux_os::GpioInput> az_cw_;
  std::unique_ptr<linux_os::GpioInput> el_down_;
  std::unique_ptr<linux_os::GpioInput> el_up_;
  std::unique_ptr<linux_os::GpioInput> pol_ccw_;
  std::unique_ptr<linux_os::GpioInput> pol_cw_;
  control::LimitSwitches limits_;
  control::LimitPair pol_limits_;
  std::function<bool()> other_hold_;
  control::PolDemand pol_demand_;  ///< the pol axis's wish, handed on at each tick unless latched
  bool latched_ = false;
  std::string latch_reason_;
  std::optional<double> held_since_s_;
};

}  // namespace azt::app
