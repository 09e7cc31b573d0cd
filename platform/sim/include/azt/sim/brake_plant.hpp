#pragma once

#include <cstdint>

#include "azt/util/result.hpp"

namespace azt::sim {

/// A spring-applied, solenoid-released axis brake in virtual time (the brake the core's
/// control::Brake drives).
///
/// Model: a release progress p in [0, 1] rises at 1/release_s while the solenoid is energised
/// and falls at 1/engage_s while it is not. Only at p = 1 is the brake off and the shaft free;
/// below it the brake holds the shaft whatever the motor does. A motor driven (duty ≠ 0) while
/// the brake holds is pulling against it: the time and the steps it happens in are recorded, so
/// a test can assert that it never happens (K3NG #55: a T-2X that starts before its brake lifts
/// does not turn; it heats the motor and strains the brake).
struct BrakePlantParams {
  double release_s = 1.2;  ///< energised this long from fully engaged to fully off
  double engage_s = 0.3;   ///< de-energised this long from fully off to holding fully

  /// Both finite and positive, at most 60 s; errors name the field.
  [[nodiscard]] Result<BrakePlantParams> validate() const;
};

class BrakePlant {
 public:
  /// Precondition: params.validate().ok(). Starts fully engaged.
  explicit BrakePlant(const BrakePlantParams& params) : params_(params) {}

  /// Advances by dt_s with the solenoid `energised` and the motor at `duty`. Returns the duty
  /// that reaches the shaft: `duty` while the brake is fully off during the whole step, else 0.
  double step(bool energised, double duty, double dt_s);

  [[nodiscard]] bool released() const { return progress_ >= 1.0; }
  [[nodiscard]] double progress() const { return progress_; }
  /// Total time and steps the motor was driven while the brake held.
  [[nodiscard]] double pulled_against_s() const { return pulled_against_s_; }
  [[nodiscard]] std::uint64_t pulled_against_steps() const { return pulled_against_steps_; }

 private:
  BrakePlantParams params_;
  double progress_ = 0.0;
  double pulled_against_s_ = 0.0;
  std::uint64_t pulled_against_steps_ = 0;
};

}  // namespace azt::sim
