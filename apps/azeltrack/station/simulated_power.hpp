#pragma once
// `[receiver] source = "sim"` (docs/calibration.md): the daemon's simulated antenna with a
// receiver, so a pointing scan works on `scripts/run` with nothing else attached. A reading is what
// the simulated receiver ([sim.receiver]) hears through the plants' true beam: their shaft angles
// through the mount's errors ([sim.mount_errors]), which the station only knows through its
// encoders and corrections. The sources' places are observed at whole seconds and interpolated
// between them (a source moves at most 0.004°/s), so a reading costs no ephemeris work.

#include <functional>
#include <optional>
#include <vector>

#include "azt/astro/sky_snapshot.hpp"
#include "azt/calibration/pointing_model.hpp"
#include "azt/sim/radio_receiver.hpp"
#include "station/sky_emitters.hpp"

namespace azt::app {

struct SimulatedPowerParts {
  SimReceiverConfig receiver;
  calibration::PointingTerms mount_errors;  ///< [sim.mount_errors]
  /// The sky at a Unix time (the station's present site); an error outside the ephemeris.
  std::function<Result<astro::SkySnapshot>(double unix_s)> sky_at;
  /// The plants' shaft angles (the truth), nullopt when unknown.
  std::function<std::optional<control::AzEl>()> shafts_deg;
};

class SimulatedPower {
 public:
  explicit SimulatedPower(SimulatedPowerParts parts);

  /// One reading at `unix_s`, dB over the system noise on cold sky; nullopt when the sky or
  /// the mount is unknown.
  std::optional<double> read_db(double unix_s);
  /// The same without the receiver's noise (what a test expects).
  [[nodiscard]] std::optional<double> expected_db(double unix_s);

 private:
  /// The emitters' places at `unix_s`, interpolated between whole seconds.
  std::optional<std::vector<sim::RadioEmitter>> sky(double unix_s);
  /// Where the true beam points (the shafts through the mount's errors) and what is in the sky.
  struct Heard {
    control::AzEl beam;
    std::vector<sim::RadioEmitter> emitters;
  };
  std::optional<Heard> heard(double unix_s);
  bool observe_second(double second, std::vector<control::AzEl>& places) const;

  SimulatedPowerParts p_;
  std::vector<SkyEmitter> emitters_;
  sim::SimulatedReceiver receiver_;
  double second_ = -1.0;             ///< the whole second `now_` and `next_` start at
  std::vector<control::AzEl> now_;   ///< each emitter's place at second_ (el below −90: none)
  std::vector<control::AzEl> next_;  ///< and at second_ + 1
};

}  // namespace azt::app
