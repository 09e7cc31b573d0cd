#pragma once
// The direction test (docs/hardware.md "Direction test"): one axis driven slowly, open loop, one
// way for one second, and which way its reading went. A motor or a sensor wired the wrong way
// round is the classic first-installation mistake; driven closed loop it shows only as a runaway
// fault, so the test asks the question directly. The station stops first (the console's STOP);
// the test is refused while tracking, while the transmitter is keyed or held, with a fault latched
// or no position; any other motion command, the console's STOP or a fault ends it early.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "antenna/antenna_backend.hpp"
#include "azt/control/modes.hpp"
#include "station/station_commands.hpp"

namespace azt::app {

struct DirectionTestParts {
  AntennaBackend& antenna;
  StationCommands& commands;
  const control::ModeController& modes;
  std::function<bool()> transmitting;  ///< the sequencer keys or holds for transmit
  std::function<double()> monotonic_s;
  bool el_fixed = false;  ///< [mount.el] fixed_deg: there is no elevation motor to test
};

/// The axis under test: azimuth, elevation, or the polarisation feed ([mount.pol]).
enum class TestedAxis : std::uint8_t { Az, El, Pol };

/// The test's answer: {axis, commanded, before_deg, after_deg, moved_deg, verdict} with verdict
/// "ok", "reversed" or "no movement"; or why it did not finish ({"error": …}).
using DirectionTestDone =
    std::function<void(nlohmann::json result, std::optional<std::string> error)>;

class DirectionTest {
 public:
  static constexpr double kDriveS = 1.0;
  /// After the drive: the soft stop and the coast, so "after" is where the shaft came to rest.
  static constexpr double kSettleS = 0.6;
  /// Less than this either way is no movement (a few counts of a 14-bit encoder).
  static constexpr double kMovedDeg = 0.05;

  explicit DirectionTest(DirectionTestParts parts) : p_(std::move(parts)) {}

  /// Starts a test of `axis` ("az", "el" or "pol") from `source`; nullopt when started (`done` is
  /// called once it ends, on the loop), else why not (and `done` is never called).
  std::optional<std::string> start(const std::string& axis, const std::string& source,
                                   DirectionTestDone done);
  /// The demand while the axis is driven; nullopt otherwise (the modes' demand stands).
  [[nodiscard]] std::optional<control::Demand> demand(double now_s) const;
  /// The pol axis's demand while its test runs (driven, then held while it settles); nullopt
  /// otherwise (the follower's demand stands).
  [[nodiscard]] std::optional<control::PolDemand> pol_demand(double now_s) const;
  /// After each antenna tick: ends the test when its time is up or something stopped it.
  void tick(double now_s);
  /// Another command was accepted (the front door's record): the test ends, unfinished.
  void interrupt(const std::string& why);
  [[nodiscard]] bool running() const { return done_ != nullptr; }

 private:
  [[nodiscard]] std::optional<std::string> refusal() const;
  /// Why the pol axis cannot be tested now: none, faulted or moving.
  [[nodiscard]] std::optional<std::string> pol_refusal() const;
  [[nodiscard]] std::optional<double> reading_deg() const;
  void finish(nlohmann::json result, std::optional<std::string> error);

  DirectionTestParts p_;
  DirectionTestDone done_;
  TestedAxis axis_ = TestedAxis::Az;
  double started_s_ = 0.0;
  double before_deg_ = 0.0;
};

}  // namespace azt::app
