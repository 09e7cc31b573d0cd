#pragma once
// A noise measurement run by the daemon (docs/calibration.md "Sun noise and the figure of
// merit"), as the pointing scans run (pointing_scanner.hpp): while the station tracks the source,
// the demand is the source plus the measurement's offset (on the source, then cold sky either
// side: calibration::NoiseMeasurement, the logic `azeltrack simulate --scenario sun-noise`
// runs), the antenna's state and the receiver's readings go to it each tick, and at the end the
// Y-factor, with what the source's flux and the dish lead to expect when they were given, is
// shown and handed to `record` (the daemon appends it to the noise log under the state
// directory). Any other command, a fault, a scan or a silent receiver ends it.

#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "azt/calibration/noise_expectation.hpp"
#include "azt/calibration/noise_measurement.hpp"
#include "azt/calibration/power_feed.hpp"
#include "azt/control/modes.hpp"
#include "azt/util/result.hpp"

namespace azt::app {

/// What a measurement should find: the station and the source at the band (both given, or none).
struct NoiseExpected {
  calibration::NoiseStation station;
  calibration::SourceAtBand source;
};

class NoiseRunner {
 public:
  /// `feed`: the receiver's readings (null: none, measurements are refused); `record`: each
  /// finished measurement's JSON, for the log.
  NoiseRunner(const calibration::PowerFeed* feed, std::function<void(nlohmann::json)> record)
      : feed_(feed), record_(std::move(record)) {}

  /// Whether a measurement could start now: a receiver that is not silent.
  [[nodiscard]] Result<bool> ready(double now_s) const;
  /// Begins a measurement of `source` (the station already tracks it); fails with the reason.
  Result<bool> start(const std::string& source, const calibration::NoisePlan& plan,
                     const calibration::ScanTiming& timing,
                     const std::optional<NoiseExpected>& expected, double now_s);
  /// Ends a running measurement, saying why ("stopped: …").
  void stop(const std::string& why);
  [[nodiscard]] bool running() const { return measurement_.has_value(); }
  [[nodiscard]] const std::string& source() const { return source_; }

  /// The position to demand with the source at `source_now`: the source plus the offset.
  [[nodiscard]] std::optional<control::AzEl> aim(const control::AzEl& source_now) const;
  /// After the antenna's tick: its state and the readings since the last tick.
  void tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders,
            const std::optional<control::AzEl>& source_now);

  /// The console's `noise`: state (idle, running, done, refused, stopped), source, plan, the
  /// pointings read, the result and the expected value, the reason.
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  void finish();
  [[nodiscard]] nlohmann::json result_json() const;

  const calibration::PowerFeed* feed_;
  std::function<void(nlohmann::json)> record_;
  std::optional<calibration::NoiseMeasurement> measurement_;
  std::optional<calibration::NoiseMeasurement> last_;  ///< finished or stopped, for display
  std::optional<NoiseExpected> expected_;
  std::optional<calibration::NoiseResult> result_;
  std::optional<control::AzEl> sky_;  ///< the source as last seen
  std::string source_;
  std::string state_ = "idle";
  std::string reason_;
  double last_reading_s_ = 0.0;
};

}  // namespace azt::app
